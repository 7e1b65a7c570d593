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
RTL_SRC    := $(wildcard rtl/*.v)

.PHONY: all help deps model render sim test bench-model lint clean
all: model

# Parameters of the render and simulation targets.
SCENE  ?= scenes/default.pov
BITS   ?= 24
TIES   ?= paper
WIDTH  ?= 320
HEIGHT ?= 240
scene_name = $(basename $(notdir $(SCENE)))

# The hardware configuration that make sim and the frame tests build
# (csgrt_top's parameters; the scene compiler checks scenes against them).
HW_MAX_LEAVES  := 64
HW_LEAF_BITS   := 6
HW_TREE_HEIGHT := 8

help:
	@echo "make deps    install missing packages (apt-get)"
	@echo "make model   build build/csgrt, the golden model and scene compiler"
	@echo "make render [SCENE=scenes/x.pov] [BITS=24] [TIES=paper|regular] [WIDTH=320] [HEIGHT=240]"
	@echo "             render with the golden model to out/model/<scene>.png"
	@echo "make sim [SCENE=scenes/x.pov] [BITS=24] [TIES=paper|regular] [TRACE=1] [WIDTH=..] [HEIGHT=..]"
	@echo "             run the RTL in Verilator; writes out/sim/<scene>.png and compares with the model"
	@echo "make test    run every test; ends with 'N passed, N failed'"
	@echo "make lint    verilator --lint-only -Wall and yosys synthesis of every RTL module"
	@echo "make bench-model  time the model, the double reference and POV-Ray at 640x480"

deps:
	@tools/deps.sh

# ---------------------------------------------------------------- the model
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

render: model
	@mkdir -p out/model
	$(BUILD)/csgrt render $(SCENE) -o out/model/$(scene_name).png --bits $(BITS) --ties $(TIES) \
	    --width $(WIDTH) --height $(HEIGHT)

# ------------------------------------------------- module testbenches, lint
include tb/tb.mk

# ------------------------------------------- csgrt_top in Verilator
# $(1): output binary, $(2): BITS, $(3): C++ driver, $(4): extra C++ flags,
# $(5): extra libraries. One build per configuration, cached under build/.
define VERILATE_TOP
	@mkdir -p $(1).obj
	@echo "verilator: building csgrt_top BITS=$(2) for $(notdir $(1)) (once per configuration)"
	@verilator --cc --exe --build -O3 -j 2 --trace-fst -Wall -y rtl --top-module csgrt_top \
	    -GBITS=$(2) -GMAX_LEAVES=$(HW_MAX_LEAVES) -GTREE_HEIGHT=$(HW_TREE_HEIGHT) \
	    -MAKEFLAGS OPT_FAST=-O2 -MAKEFLAGS OPT_SLOW=-O1 -MAKEFLAGS OPT_GLOBAL=-O2 \
	    -CFLAGS "-std=c++17 -O2 -I$(CURDIR)/model -I$(CURDIR)/sim $(4)" \
	    -LDFLAGS "$(CURDIR)/$(BUILD)/libcsgrt.a $(PKG_LIBS) $(5) -pthread" \
	    --Mdir $(1).obj -o $(CURDIR)/$(1) $(CURDIR)/rtl/csgrt_top.v $(CURDIR)/$(3) \
	    > $(1).log 2>&1 || { tail -30 $(1).log; exit 1; }
endef

# the frame testbench: whole frames at 16 and 24 bits against the model
FRAME_BITS := 16 24
FRAME_BINS := $(FRAME_BITS:%=$(BUILD)/tb/frame%)
$(BUILD)/tb/frame%: $(RTL_SRC) tb/frame/tb_frame.cpp $(wildcard sim/*.h) $(BUILD)/libcsgrt.a | deps
	$(call VERILATE_TOP,$@,$*,tb/frame/tb_frame.cpp,-DFRAME_BITS=$*,-lgtest -lgtest_main)

# make sim: the project's main job
SIM_BIN = $(BUILD)/sim/b$(BITS)/csgrt_sim
SIM_OUT = out/sim/$(scene_name)
$(BUILD)/sim/b%/csgrt_sim: $(RTL_SRC) $(wildcard sim/*.cpp sim/*.h) $(BUILD)/libcsgrt.a | deps
	$(call VERILATE_TOP,$@,$*,sim/sim_main.cpp,-DCSGRT_LEAF_BITS=$(HW_LEAF_BITS) -DCSGRT_TREE_HEIGHT=$(HW_TREE_HEIGHT),)

sim: model $(SIM_BIN)
	@mkdir -p out/sim
	@$(BUILD)/csgrt compile $(SCENE) -o $(SIM_OUT).bin --bits $(BITS) --width $(WIDTH) --height $(HEIGHT) \
	    --max-leaves $(HW_MAX_LEAVES) --tree-height $(HW_TREE_HEIGHT)
	@$(SIM_BIN) --scene-image $(SIM_OUT).bin --out $(SIM_OUT).png --ties $(TIES) $(if $(TRACE),--trace $(SIM_OUT).fst)

# ------------------------------------------------------------------ checks
test: deps $(BUILD)/csgrt $(BUILD)/model_tests $(TB_BINS) $(FRAME_BINS)
	@tools/run_tests.sh $(BUILD)/model_tests $(TB_BINS) $(FRAME_BINS)

lint: deps lint-rtl

bench-model: model
	@tools/bench_model.sh

clean:
	rm -rf $(BUILD) out

-include $(MODEL_OBJ:.o=.d) $(TEST_OBJ:.o=.d) $(BUILD)/model/main.d
