# csgrt — top-level Makefile. `make help` lists the targets.
#
# Every target depends on `deps`, which installs missing Debian packages once
# (idempotent, silent when satisfied).

SHELL      := /bin/bash
BUILD      := build
CXX        ?= g++
CXXFLAGS   ?= -O2 -g
CXXFLAGS   += -std=c++17 -Wall -Wextra -pthread -MMD -MP
PKGS       := OpenImageIO glm
PKG_CFLAGS  = $(shell pkg-config --cflags $(PKGS) 2>/dev/null)
PKG_LIBS    = $(shell pkg-config --libs $(PKGS) 2>/dev/null)

MODEL_SRC  := $(filter-out model/main.cpp model/%_test.cpp,$(wildcard model/*.cpp))
MODEL_OBJ  := $(MODEL_SRC:model/%.cpp=$(BUILD)/model/%.o)
TEST_SRC   := $(wildcard model/*_test.cpp)
TEST_OBJ   := $(TEST_SRC:model/%.cpp=$(BUILD)/model/%.o)

.PHONY: all help deps model render sim test bench-model lint clean
all: model

# Parameters of the render and simulation targets.
SCENE ?= scenes/default.pov
BITS  ?= 24
TIES  ?= paper
WIDTH ?= 320
HEIGHT ?= 240
scene_name = $(basename $(notdir $(SCENE)))

help:
	@echo "make deps    install missing packages (apt-get)"
	@echo "make model   build build/csgrt, the golden model and scene compiler"
	@echo "make render [SCENE=scenes/x.pov] [BITS=24] [TIES=paper|regular] [WIDTH=320] [HEIGHT=240]"
	@echo "             render with the golden model to out/model/<scene>.png"
	@echo "make sim [SCENE=scenes/x.pov] [BITS=24] [TIES=paper|regular] [TRACE=1]"
	@echo "             run the RTL in Verilator; writes out/sim/<scene>.png and compares with the model"
	@echo "make test    run every test; ends with 'N passed, N failed'"
	@echo "make bench-model  time the model, the double reference and POV-Ray at 640x480"
	@echo "make lint    verilator --lint-only -Wall and yosys synthesis of every RTL module"

deps:
	@tools/deps.sh

model: deps $(BUILD)/csgrt

$(BUILD)/model/%.o: model/%.cpp | deps
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS) $(PKG_CFLAGS) -c $< -o $@

$(BUILD)/libcsgrt.a: $(MODEL_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/csgrt: $(BUILD)/model/main.o $(BUILD)/libcsgrt.a
	$(CXX) $(CXXFLAGS) $^ $(PKG_LIBS) -o $@

$(BUILD)/model_tests: $(TEST_OBJ) $(BUILD)/libcsgrt.a
	$(CXX) $(CXXFLAGS) $^ $(PKG_LIBS) -lgtest -lgtest_main -o $@

include tb/tb.mk

test: deps $(BUILD)/csgrt $(BUILD)/model_tests $(TB_BINS)
	@tools/run_tests.sh $(BUILD)/model_tests $(TB_BINS)

render: model
	@mkdir -p out/model
	$(BUILD)/csgrt render $(SCENE) -o out/model/$(scene_name).png --bits $(BITS) --ties $(TIES) \
	    --width $(WIDTH) --height $(HEIGHT)

lint: deps lint-rtl

# ---- make sim: the RTL in Verilator, one build per configuration
SIM_MAX_LEAVES  := 64
SIM_LEAF_BITS   := 6
SIM_TREE_HEIGHT := 8
SIM_DIR  = $(BUILD)/sim/b$(BITS)
SIM_BIN  = $(SIM_DIR)/csgrt_sim
SIM_OUT  = out/sim/$(scene_name)
$(BUILD)/sim/b%/csgrt_sim: $(wildcard rtl/*.v) $(wildcard sim/*.cpp sim/*.h) $(BUILD)/libcsgrt.a
	@mkdir -p $(BUILD)/sim/b$*/obj
	@echo "sim: building the Verilator model for BITS=$* (once per configuration)"
	verilator --cc --exe --build -O3 -j 2 --trace-fst -Wall -y rtl --top-module csgrt_top \
	    -GBITS=$* -GMAX_LEAVES=$(SIM_MAX_LEAVES) -GTREE_HEIGHT=$(SIM_TREE_HEIGHT) \
	    -MAKEFLAGS OPT_FAST=-O2 -MAKEFLAGS OPT_SLOW=-O1 -MAKEFLAGS OPT_GLOBAL=-O2 \
	    -CFLAGS "-std=c++17 -O2 -I$(CURDIR)/model -I$(CURDIR)/sim -DCSGRT_LEAF_BITS=$(SIM_LEAF_BITS) -DCSGRT_TREE_HEIGHT=$(SIM_TREE_HEIGHT)" \
	    -LDFLAGS "$(CURDIR)/$(BUILD)/libcsgrt.a $(PKG_LIBS) -pthread" \
	    --Mdir $(BUILD)/sim/b$*/obj -o $(CURDIR)/$@ $(CURDIR)/rtl/csgrt_top.v $(CURDIR)/sim/sim_main.cpp > $(BUILD)/sim/b$*/build.log 2>&1 \
	    || { tail -30 $(BUILD)/sim/b$*/build.log; exit 1; }

# the frame testbench: csgrt_top at 16 and 24 bits against the model
FRAME_BITS := 16 24
FRAME_BINS := $(FRAME_BITS:%=$(BUILD)/tb/frame%)
$(BUILD)/tb/frame%: $(wildcard rtl/*.v) tb/frame/tb_frame.cpp $(wildcard sim/*.h) $(BUILD)/libcsgrt.a
	@mkdir -p $(BUILD)/tb/frame$*.obj
	@echo "tb: building the frame testbench for BITS=$*"
	verilator --cc --exe --build -O3 -j 2 --trace-fst -Wall -y rtl --top-module csgrt_top \
	    -GBITS=$* -GMAX_LEAVES=$(SIM_MAX_LEAVES) -GTREE_HEIGHT=$(SIM_TREE_HEIGHT) \
	    -MAKEFLAGS OPT_FAST=-O2 -MAKEFLAGS OPT_SLOW=-O1 -MAKEFLAGS OPT_GLOBAL=-O2 \
	    -CFLAGS "-std=c++17 -O2 -I$(CURDIR)/model -I$(CURDIR)/sim -DFRAME_BITS=$*" \
	    -LDFLAGS "$(CURDIR)/$(BUILD)/libcsgrt.a $(PKG_LIBS) -lgtest -lgtest_main -pthread" \
	    --Mdir $(BUILD)/tb/frame$*.obj -o $(CURDIR)/$@ $(CURDIR)/rtl/csgrt_top.v $(CURDIR)/tb/frame/tb_frame.cpp \
	    > $(BUILD)/tb/frame$*.log 2>&1 || { tail -30 $(BUILD)/tb/frame$*.log; exit 1; }

sim: model $(SIM_BIN)
	@mkdir -p out/sim
	@$(BUILD)/csgrt compile $(SCENE) -o $(SIM_OUT).bin --bits $(BITS) --width $(WIDTH) --height $(HEIGHT) \
	    --max-leaves $(SIM_MAX_LEAVES) --tree-height $(SIM_TREE_HEIGHT)
	@$(SIM_BIN) --scene-image $(SIM_OUT).bin --out $(SIM_OUT).png --ties $(TIES) $(if $(TRACE),--trace $(SIM_OUT).fst)

bench-model: model
	@tools/bench_model.sh

clean:
	rm -rf $(BUILD) out

-include $(MODEL_OBJ:.o=.d) $(TEST_OBJ:.o=.d) $(BUILD)/model/main.d
