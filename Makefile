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
RTL_SRC    := $(wildcard rtl/*.v) $(wildcard rtl/*.vh)

.PHONY: all help deps model render sim sim-run test bench-model lint clean synth timing-modules logic-depth
all: model

# Parameters of the render and simulation targets.
SCENE  ?= scenes/default.pov
comma  := ,
BITS   ?= 24
TIES   ?= paper
WIDTH  ?= 320
HEIGHT ?= 240
scene_name = $(basename $(notdir $(SCENE)))

# The hardware configuration that make sim and the frame tests build
# (csgrt_top's parameters; the scene compiler checks scenes against them).
# TREE_HEIGHT=H (make sim and make synth) builds the classification tree
# for trees of height H (2^H leaf slots) with a leaf store of 2^(H-1)
# leaves, 2 to 64, as tools/synth.sh does (tools/synth_args_test.py checks
# that the lists below and the script agree): TREE_HEIGHT=5 simulates the
# 16-leaf build routed in docs/fpga.md. make sim's binary for another
# height than 8 gets the suffix hH.
TREE_HEIGHT ?=
ifneq ($(TREE_HEIGHT),)
ifeq ($(filter 1 2 3 4 5 6 7 8 9 10,$(TREE_HEIGHT)),)
$(error TREE_HEIGHT takes 1 to 10, not '$(TREE_HEIGHT)')
endif
endif
HW_TREE_HEIGHT := $(or $(TREE_HEIGHT),8)
HW_MAX_LEAVES  := $(word $(HW_TREE_HEIGHT),2 2 4 8 16 32 64 64 64 64)
HW_LEAF_BITS   := $(word $(HW_TREE_HEIGHT),1 1 2 3 4 5 6 6 6 6)
UNITS          ?= 1
# effect units of a simulation build: `scene` (what the scene uses; one
# cached build per effect set), `all`, or `none`
EFFECTS        ?= scene

help:
	@echo "make deps    install missing packages (apt-get)"
	@echo "make model   build build/csgrt, the golden model and scene compiler"
	@echo "make render [SCENE=scenes/x.pov] [BITS=24] [TIES=paper|regular] [WIDTH=320] [HEIGHT=240]"
	@echo "             render with the golden model to out/model/<scene>.png"
	@echo "make sim [SCENE=scenes/x.pov] [BITS=24] [TIES=paper|regular] [TRACE=1] [UNITS=1] [ISECT_II=3] [CONTEXTS=8] [MAX_LIGHTS=8] [TREE_HEIGHT=8] [WIDTH=..] [HEIGHT=..]"
	@echo "             run the RTL in Verilator; writes out/sim/<scene>.png and compares with the model"
	@echo "make test    run every test; ends with 'N passed, N failed'"
	@echo "make synth [BITS=24] [EFFECTS=none|all|shadows,reflection,...] [SPECULAR=0] [SHARE_II=1] [ISECT_II=3] [CONTEXTS=16] [MAX_LIGHTS=4] [LUT_TILE_MAX=81] [TREE_HEIGHT=7] [FREQ=100] [BAUD=3000000]"
	@echo "             ULX3S bitstream (yosys, nextpnr-ecp5, ecppack) to out/synth/; docs/fpga.md"
	@echo "make timing-modules [MODULES=\"csgrt_walker ...\"] [BITS=24] [EFFECTS=shadows,reflection]"
	@echo "             each module placed and routed alone on the 85F: Fmax and critical path (docs/fpga.md)"
	@echo "make logic-depth [NETLIST=out/synth/csgrt.json]"
	@echo "             the whole design's longest paths and largest fan-outs in make synth's netlist, before placement"
	@echo "make lint    verilator --lint-only -Wall and yosys synthesis of every RTL module"
	@echo "make bench-model  time the model, the double reference and POV-Ray at 640x480"
	@echo "make stability    the paper's hard cases: random transforms x widths x ties x {exact, epsilon}"
	@echo "make hard-cases   write docs/hard-cases.md (montages: exact | epsilon | POV-Ray)"

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
# $(5): extra libraries, $(6): NUM_UNITS, $(7): effect units (-GSHADOWS=..),
# $(8): more verilator flags (--trace-fst for make sim's TRACE=1: the frame
# benches leave it out, which takes about a third of the C++ off each build).
# One build per configuration, cached under build/.
define VERILATE_TOP
	@mkdir -p $(1).obj
	@echo "verilator: building csgrt_top BITS=$(2) $(7) for $(notdir $(1)) (once per configuration)"
	@verilator --cc --exe --build -O3 -j 2 $(8) -Wall -y rtl --top-module csgrt_top \
	    -GBITS=$(2) -GMAX_LEAVES=$(HW_MAX_LEAVES) -GTREE_HEIGHT=$(HW_TREE_HEIGHT) -GNUM_UNITS=$(6) $(7) \
	    -MAKEFLAGS OPT_FAST=-O2 -MAKEFLAGS OPT_SLOW=-O1 -MAKEFLAGS OPT_GLOBAL=-O2 \
	    -CFLAGS "-std=c++17 -O2 -I$(CURDIR)/model -I$(CURDIR)/sim $(4)" \
	    -LDFLAGS "$(CURDIR)/$(BUILD)/libcsgrt.a $(PKG_LIBS) $(5) -pthread" \
	    --Mdir $(1).obj -o $(CURDIR)/$(1) $(CURDIR)/rtl/csgrt_top.v $(CURDIR)/$(3) \
	    > $(1).log 2>&1 || { tail -30 $(1).log; exit 1; }
endef

# the frame testbench: whole frames at 16 and 24 bits against the model, and
# with two intersection lanes; the two-lane builds are also the ones without
# the specular unit (SPECULAR=0: every scene shaded without highlights, the
# model likewise), so that both shading configurations are co-simulated
# without a build of their own; frame24u2 is also the one whose event
# sorters insert two events per clock (SORT_INSERTS=2; the others: 1), and
# the two-lane builds run the time-shared blocks (camera, shading, ray tree
# arithmetic, spawn children) at an item per clock (SHARE_II=1; the others: 3);
# frame16fxu2 is also built for two lights (MAX_LIGHTS=2; the others: 8):
# the three-light scene is refused there (status 4)
FRAME_BINS := $(BUILD)/tb/frame16 $(BUILD)/tb/frame24 $(BUILD)/tb/frame24u2 \
              $(BUILD)/tb/frame16fx $(BUILD)/tb/frame24fx $(BUILD)/tb/frame16fxu2 $(BUILD)/tb/frame24fxi3
FRAME_DEPS := $(RTL_SRC) tb/frame/tb_frame.cpp $(wildcard sim/*.h) $(BUILD)/libcsgrt.a
$(BUILD)/tb/frame%: $(FRAME_DEPS) | deps
	$(call VERILATE_TOP,$@,$*,tb/frame/tb_frame.cpp,-DFRAME_BITS=$* -DFRAME_UNITS=1,-lgtest -lgtest_main,1)
$(BUILD)/tb/frame24u2: $(FRAME_DEPS) | deps
	$(call VERILATE_TOP,$@,24,tb/frame/tb_frame.cpp,-DFRAME_BITS=24 -DFRAME_UNITS=2 -DFRAME_SPECULAR=0,-lgtest -lgtest_main,2,-GSPECULAR=0 -GSORT_INSERTS=2 -GSHARE_II=1)
# with every effect unit (the ray tree: shadows, reflection, refraction);
# frame16fx with 16 ray-tree contexts, frame24fx with the default 8
FX_UNITS := -GSHADOWS=1 -GREFLECTION=1 -GREFRACTION=1
FX_DEFS  := -DFRAME_UNITS=1 -DFRAME_SHADOWS=1 -DFRAME_REFLECTION=1 -DFRAME_REFRACTION=1
$(BUILD)/tb/frame16fx: $(FRAME_DEPS) | deps
	$(call VERILATE_TOP,$@,16,tb/frame/tb_frame.cpp,-DFRAME_BITS=16 $(FX_DEFS),-lgtest -lgtest_main,1,$(FX_UNITS) -GCONTEXTS=16)
$(BUILD)/tb/frame24fx: $(FRAME_DEPS) | deps
	$(call VERILATE_TOP,$@,24,tb/frame/tb_frame.cpp,-DFRAME_BITS=24 $(FX_DEFS),-lgtest -lgtest_main,1,$(FX_UNITS))
# frame24fx's configuration with the time-shared intersection unit
# (ISECT_II=3: a pair every three clocks on a third of its multipliers)
$(BUILD)/tb/frame24fxi3: $(FRAME_DEPS) | deps
	$(call VERILATE_TOP,$@,24,tb/frame/tb_frame.cpp,-DFRAME_BITS=24 $(FX_DEFS),-lgtest -lgtest_main,1,$(FX_UNITS) -GISECT_II=3)
# shadows and reflection with two intersection lanes (refraction needs one lane)
$(BUILD)/tb/frame16fxu2: $(FRAME_DEPS) | deps
	$(call VERILATE_TOP,$@,16,tb/frame/tb_frame.cpp,-DFRAME_BITS=16 -DFRAME_UNITS=2 -DFRAME_SHADOWS=1 -DFRAME_REFLECTION=1 -DFRAME_REFRACTION=0 -DFRAME_SPECULAR=0 -DFRAME_MAX_LIGHTS=2,-lgtest -lgtest_main,2,-GSHADOWS=1 -GREFLECTION=1 -GSPECULAR=0 -GSHARE_II=1 -GMAX_LIGHTS=2)

# make sim: the project's main job. The build has the effect units the
# scene uses (`csgrt units`: shadows, reflection, refraction, specular
# highlights), or all of them (EFFECTS=all), or none (EFFECTS=none: primary
# rays, local shading with highlights); each combination is its own cached
# Verilator build.
SHADOWS    ?= 0
REFLECTION ?= 0
REFRACTION ?= 0
SPECULAR   ?= 1
# the event sorter's insertions per clock (csgrt_top SORT_INSERTS: 1, or 2
# with more logic for 0-3 % fewer cycles; docs/architecture.md); a build
# with 2 gets the suffix i2
SORT_INSERTS ?= 1
# the clocks per item of the camera, the shading, the ray tree's arithmetic
# and the secondary rays' children (csgrt_top SHARE_II: 3,
# a third of their multipliers; or 1, ~1 % fewer cycles on scenes with many
# leaves, up to a third fewer where the ray tree's contexts bound the rate;
# docs/architecture.md "Contexts"); a build with 1 gets the suffix ii1
SHARE_II ?= 3
# the intersection unit's clocks per ray-primitive pair (csgrt_top ISECT_II:
# 1, or 3 on a third of its multipliers, for the FPGA's routing; 1.3 to 3
# times the cycles on the effect scenes); a build with 3 gets the suffix x3
ISECT_II ?= 1
# pixels in flight in the ray tree (csgrt_top CONTEXTS, a power of two):
# with few leaves per scene the contexts, not the intersection unit, bound
# the rate (docs/architecture.md "Contexts"); a build with another number
# than 8 gets the suffix cN
CONTEXTS ?= 8
# point lights a scene may have (csgrt_top MAX_LIGHTS, 1..8): a build for
# fewer has fewer light registers and wires (docs/fpga.md); the loader
# refuses a scene with more (status 4); another number than 8 gets the
# suffix lN
MAX_LIGHTS ?= 8
ifeq ($(filter 1 2 3 4 5 6 7 8,$(MAX_LIGHTS)),)
$(error MAX_LIGHTS takes 1 to 8, not '$(MAX_LIGHTS)')
endif
# TRACE=1 builds a binary of its own with waveform tracing (suffix t): a
# build Verilated with --trace-fst runs about 15 % slower even when it
# writes no waveform (quadrics 64x48 B24: 1.13 s against 1.01 s, median of 5)
SIM_FX  = s$(SHADOWS)r$(REFLECTION)f$(REFRACTION)p$(SPECULAR)$(if $(filter 2,$(SORT_INSERTS)),i2,)$(if $(filter 1,$(SHARE_II)),ii1,)$(if $(filter 3,$(ISECT_II)),x3,)$(if $(filter-out 8,$(CONTEXTS)),c$(CONTEXTS),)$(if $(filter-out 8,$(MAX_LIGHTS)),l$(MAX_LIGHTS),)$(if $(filter-out 8,$(HW_TREE_HEIGHT)),h$(HW_TREE_HEIGHT),)$(if $(TRACE),t,)
SIM_BIN = $(BUILD)/sim/b$(BITS)u$(UNITS)$(SIM_FX)/csgrt_sim
SIM_OUT = out/sim/$(scene_name)
$(BUILD)/sim/b$(BITS)u$(UNITS)$(SIM_FX)/csgrt_sim: $(RTL_SRC) $(wildcard sim/*.cpp sim/*.h) $(BUILD)/libcsgrt.a | deps
	$(call VERILATE_TOP,$@,$(BITS),sim/sim_main.cpp,-DCSGRT_LEAF_BITS=$(HW_LEAF_BITS) -DCSGRT_TREE_HEIGHT=$(HW_TREE_HEIGHT) -DCSGRT_NUM_UNITS=$(UNITS) -DCSGRT_SHADOWS=$(SHADOWS) -DCSGRT_REFLECTION=$(REFLECTION) -DCSGRT_REFRACTION=$(REFRACTION) -DCSGRT_SPECULAR=$(SPECULAR) -DCSGRT_CONTEXTS=$(CONTEXTS),,$(UNITS),-GSHADOWS=$(SHADOWS) -GREFLECTION=$(REFLECTION) -GREFRACTION=$(REFRACTION) -GSPECULAR=$(SPECULAR) -GSORT_INSERTS=$(SORT_INSERTS) -GSHARE_II=$(SHARE_II) -GISECT_II=$(ISECT_II) -GCONTEXTS=$(CONTEXTS) -GMAX_LIGHTS=$(MAX_LIGHTS),$(if $(TRACE),--trace-fst))

sim: model
	@units="$(if $(filter all,$(EFFECTS)),SHADOWS=1 REFLECTION=1 REFRACTION=1 SPECULAR=1,$(if $(filter none,$(EFFECTS)),SHADOWS=0 REFLECTION=0 REFRACTION=0 SPECULAR=1,$$($(BUILD)/csgrt units $(SCENE))))" \
	    && if [ "$(UNITS)" != 1 ] && [ "$${units#*REFRACTION=1}" != "$$units" ]; then \
	        echo "make sim: refraction works with one intersection lane for now: UNITS=$(UNITS) builds without it"; \
	        units="$${units/REFRACTION=1/REFRACTION=0}"; fi \
	    && echo "make sim: effect units $$units (EFFECTS=$(EFFECTS))" \
	    && $(MAKE) --no-print-directory sim-run $$units

sim-run: $(SIM_BIN)
	@mkdir -p out/sim
	@$(BUILD)/csgrt compile $(SCENE) -o $(SIM_OUT).bin --bits $(BITS) --width $(WIDTH) --height $(HEIGHT) \
	    --max-leaves $(HW_MAX_LEAVES) --tree-height $(HW_TREE_HEIGHT)
	@$(SIM_BIN) --scene-image $(SIM_OUT).bin --out $(SIM_OUT).png --ties $(TIES) $(if $(TRACE),--trace $(SIM_OUT).fst)

# ------------------------------------------- FPGA: ULX3S board top, synthesis
# docs/fpga.md. `make synth [BITS=24] [EFFECTS=none|all|shadows,reflection,refraction]
# [FREQ=100] [BAUD=3000000]`: yosys synth_ecp5, nextpnr-ecp5, ecppack for the
# ULX3S (LFE5U-85F); the summary goes to out/synth/report.json; non-zero exit
# when the clock is missed. EFFECTS: csgrt_top's effect units (the default
# `scene` of make sim means none here).
FREQ ?= 100
BAUD ?= 3000000
synth: deps
	@tools/synth.sh --bits $(BITS) --effects $(if $(filter scene,$(EFFECTS)),none,$(EFFECTS)) \
	    $(if $(filter 0,$(SPECULAR)),--no-specular) $(if $(filter 2,$(SORT_INSERTS)),--sort-inserts 2) \
	    $(if $(filter 1,$(SHARE_II)),--share-ii 1) \
	    $(if $(filter 3,$(ISECT_II)),--isect-ii 3) \
	    $(if $(filter-out 1,$(UNITS)),--units $(UNITS)) \
	    $(if $(filter-out 8,$(CONTEXTS)),--contexts $(CONTEXTS)) \
	    $(if $(filter-out 8,$(MAX_LIGHTS)),--max-lights $(MAX_LIGHTS)) \
	    $(if $(LUT_TILE_MAX),--lut-tile-max $(LUT_TILE_MAX)) \
	    $(if $(TREE_HEIGHT),--tree-height $(TREE_HEIGHT)) \
	    --freq $(FREQ) --baud $(BAUD) $(SYNTH_FLAGS)

# Out-of-context timing (a benchmark, not a test; docs/fpga-timing.md "Timing per
# module"): each module of csgrt_top's configuration placed and routed alone
# on the 85F, its Fmax and critical path with the RTL lines, minutes per
# module instead of hours for the whole design.
# `make timing-modules [MODULES="csgrt_walker ..."] [BITS=24] [EFFECTS=shadows,reflection]`
TIMING_MODULES ?= csgrt_event_sort csgrt_class_tree csgrt_walker csgrt_camera csgrt_dispatch \
                  csgrt_hit_prep csgrt_raytree csgrt_spawn csgrt_shade
timing-modules: deps
	@python3 tools/module_timing.py $(or $(MODULES),$(TIMING_MODULES)) --bits $(BITS) \
	    --effects $(if $(filter scene,$(EFFECTS)),shadows$(comma)reflection,$(EFFECTS)) \
	    --tree-height $(or $(TREE_HEIGHT),7) --lut-tile-max $(or $(LUT_TILE_MAX),81) --freq $(FREQ)

# Whole-design paths without place and route (docs/fpga-timing.md "Whole-design
# paths"): the longest register-to-register paths, across modules too, and
# the largest fan-outs of make synth's netlist (yosys JSON), by a fixed
# delay per cell and net. `make logic-depth [NETLIST=out/synth/csgrt.json]`
logic-depth:
	@python3 tools/logic_depth.py $(or $(NETLIST),out/synth/csgrt.json) --freq $(FREQ)

# the board top in Verilator with a UART model (tb/board/), built as the
# FPGA build is (CSGRT_ECP5_DSP: csgrt_mul in MULT18X18D tiles): the ECP5
# primitives replaced by the models in tb/ecp5/ (EHXPLLL, MULT18X18D),
# BOARD_UART_DIV clocks per UART bit
BOARD_BITS     := 24
BOARD_UART_DIV := 4
BOARD_IDLE     := 2000
BOARD_BIN      := $(BUILD)/tb/board
BOARD_SRC      := $(wildcard rtl/board/*.v rtl/board/ulx3s/*.v tb/ecp5/*.v)
$(BOARD_BIN): $(RTL_SRC) $(BOARD_SRC) tb/board/tb_board.cpp $(BUILD)/libcsgrt.a | deps
	@mkdir -p $@.obj
	@echo "verilator: building csgrt_ulx3s BITS=$(BOARD_BITS) for $(notdir $@)"
	@verilator --cc --exe --build -O3 -j 2 -Wall -DCSGRT_ECP5_DSP -y rtl -y rtl/board -y rtl/board/ulx3s -y tb/ecp5 \
	    --top-module csgrt_ulx3s -GBITS=$(BOARD_BITS) -GUART_DIV=$(BOARD_UART_DIV) -GIDLE_CLOCKS=$(BOARD_IDLE) \
	    -MAKEFLAGS OPT_FAST=-O2 -MAKEFLAGS OPT_SLOW=-O1 -MAKEFLAGS OPT_GLOBAL=-O2 \
	    -CFLAGS "-std=c++17 -O2 -I$(CURDIR)/model -DBOARD_BITS=$(BOARD_BITS) -DBOARD_UART_DIV=$(BOARD_UART_DIV) -DBOARD_IDLE_CLOCKS=$(BOARD_IDLE)" \
	    -LDFLAGS "$(CURDIR)/$(BUILD)/libcsgrt.a $(PKG_LIBS) -lgtest -lgtest_main -pthread" \
	    --Mdir $@.obj -o $(CURDIR)/$@ $(CURDIR)/rtl/board/ulx3s/csgrt_ulx3s.v $(CURDIR)/tb/board/tb_board.cpp \
	    > $@.log 2>&1 || { tail -30 $@.log; exit 1; }

# ------------------------------------------------------------------ checks
test: deps $(BUILD)/csgrt $(BUILD)/model_tests $(TB_BINS) $(FRAME_BINS) $(BOARD_BIN) accuracy-smoke
	@tools/run_tests.sh $(BUILD)/model_tests $(TB_BINS) $(FRAME_BINS) $(BOARD_BIN) tools/accuracy_test.py tools/logic_depth_test.py tools/congestion_test.py tools/synth_args_test.py

lint: deps lint-rtl

bench-model: model
	@tools/bench_model.sh

# the hard-case stability suite (model/stability.h) and its report
# the specialised-versus-full simulation builds of the effect scenes
bench-effects: model
	@tools/bench_effects.sh

.PHONY: stability hard-cases bench-effects
stability: model
	@$(BUILD)/csgrt stability

hard-cases: model
	@tools/hard_cases.sh

# the precision sweep and its report (tools/accuracy.py: docs/accuracy/results.csv,
# docs/accuracy.md); resumes where it stopped. ACCURACY_FLAGS e.g. --no-synth,
# --bits 16,24, --synth-tree-height 6, --stop-after-synth, --force
.PHONY: accuracy accuracy-smoke
ACCURACY_FLAGS ?=
accuracy: model
	@/usr/bin/python3 tools/accuracy.py $(ACCURACY_FLAGS)

# the simulation build the sweep's smoke test in make test (tools/accuracy_test.py) runs
accuracy-smoke: model
	@$(MAKE) --no-print-directory $(BUILD)/sim/b16u1s1r1f1p1/csgrt_sim BITS=16 UNITS=1 SHADOWS=1 REFLECTION=1 REFRACTION=1 SPECULAR=1

clean:
	rm -rf $(BUILD) out

-include $(MODEL_OBJ:.o=.d) $(TEST_OBJ:.o=.d) $(BUILD)/model/main.d
