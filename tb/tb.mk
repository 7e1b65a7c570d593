# tb/tb.mk — Verilator testbenches and RTL lint/synthesis checks.
# Included by the top-level Makefile (`include tb/tb.mk`), which provides
# BUILD, PKG_LIBS and the rule for $(BUILD)/libcsgrt.a.
#
#   make build/tb/<name>   build one testbench (sqrt, div, isect)
#   make lint-rtl          verilator --lint-only -Wall and yosys synth + check
#                          on every module in rtl/
#
# Each testbench is a googletest binary: Verilator objects live under
# $(BUILD)/tb/<name>.obj/, the binary is $(BUILD)/tb/<name>.

BUILD        ?= build
VERILATOR    ?= verilator
YOSYS        ?= yosys
TB_NAMES     := sqrt div isect camera shade
TB_NAMES     += class_node class_tree walk spawn quadric_at mul mul_vec fifo
TB_BINS      := $(TB_NAMES:%=$(BUILD)/tb/%)
# the multiplier bench once more as the FPGA build maps csgrt_mul (MULT18X18D tiles)
TB_BINS      += $(BUILD)/tb/mul_ecp5 $(BUILD)/tb/mul_ecp5_t0 $(BUILD)/tb/mul_ecp5_t81 $(BUILD)/tb/mul_ecp5_treg $(BUILD)/tb/mul_vec_treg
TB_BINS      += $(BUILD)/tb/mul_vec_oreg $(BUILD)/tb/mul_vec_noop
ECP5_MODELS  := $(wildcard tb/ecp5/*.v)
TB_RTL       := $(wildcard rtl/*.v)
TB_RTL_INC   := $(wildcard rtl/*.vh)   # included by the modules: dependencies only
TB_COMMON    := $(wildcard tb/common/*.h)
TB_VFLAGS    := --cc --exe --build -Wall -O3 -j 2 -y rtl \
                -MAKEFLAGS OPT_FAST=-O2 -MAKEFLAGS OPT_SLOW=-O1 -MAKEFLAGS OPT_GLOBAL=-O2
TB_CXXFLAGS  := -std=c++17 -O2 -I$(CURDIR)/model -I$(CURDIR)/tb/common
TB_LDLIBS    := -lgtest -lgtest_main -pthread
# the intersection bench links the golden model's library
TB_LIB_isect  = $(CURDIR)/$(BUILD)/libcsgrt.a $(PKG_LIBS)
TB_DEP_isect := $(BUILD)/libcsgrt.a
# so do the classification and walk benches (csgrt_class_node/_tree, csgrt_walk_unit)
TB_LIB_class_node := $(TB_LIB_isect)
TB_DEP_class_node := $(TB_DEP_isect)
TB_LIB_class_tree := $(TB_LIB_isect)
TB_DEP_class_tree := $(TB_DEP_isect)
TB_LIB_walk       := $(TB_LIB_isect)
TB_DEP_walk       := $(TB_DEP_isect)
# so do the camera and shading benches
TB_LIB_camera := $(TB_LIB_isect)
TB_DEP_camera := $(TB_DEP_isect)
TB_LIB_shade  := $(TB_LIB_isect)
TB_DEP_shade  := $(TB_DEP_isect)
# and the secondary-ray geometry bench (csgrt_spawn)
TB_LIB_spawn  := $(TB_LIB_isect)
TB_DEP_spawn  := $(TB_DEP_isect)
# and the look-ahead's quadric test (csgrt_quadric_at)
TB_LIB_quadric_at := $(TB_LIB_isect)
TB_DEP_quadric_at := $(TB_DEP_isect)

# $(1): testbench name (folder tb/$(1)/ with tb_$(1).v and tb_$(1).cpp)
define TB_RULE
$(BUILD)/tb/$(1): tb/$(1)/tb_$(1).v tb/$(1)/tb_$(1).cpp $(TB_RTL) $(TB_RTL_INC) $(TB_COMMON) $(TB_DEP_$(1)) model/fixed.h
	@mkdir -p $(BUILD)/tb/$(1).obj
	$(VERILATOR) $(TB_VFLAGS) --Mdir $(BUILD)/tb/$(1).obj --top-module tb_$(1) \
	    -CFLAGS "$(TB_CXXFLAGS)" -LDFLAGS "$$(TB_LIB_$(1)) $(TB_LDLIBS)" \
	    -o $(CURDIR)/$(BUILD)/tb/$(1) $(CURDIR)/tb/$(1)/tb_$(1).v $(CURDIR)/tb/$(1)/tb_$(1).cpp
endef
$(foreach t,$(TB_NAMES),$(eval $(call TB_RULE,$(t))))

# A bench built as the FPGA build maps csgrt_mul (MULT18X18D tiles):
# $(1) binary name, $(2) the bench (tb/$(2)/tb_$(2).v and .cpp), $(3)
# parameters and defines beyond CSGRT_ECP5_DSP
define ECP5_TB_RULE
$(BUILD)/tb/$(1): tb/$(2)/tb_$(2).v tb/$(2)/tb_$(2).cpp $(TB_RTL) $(TB_RTL_INC) $(TB_COMMON) $(ECP5_MODELS)
	@mkdir -p $(BUILD)/tb/$(1).obj
	$(VERILATOR) $(TB_VFLAGS) -y tb/ecp5 -DCSGRT_ECP5_DSP $(3) --Mdir $(BUILD)/tb/$(1).obj --top-module tb_$(2) \
	    -CFLAGS "$(TB_CXXFLAGS)" -LDFLAGS "$(TB_LDLIBS)" \
	    -o $(CURDIR)/$(BUILD)/tb/$(1) $(CURDIR)/tb/$(2)/tb_$(2).v $(CURDIR)/tb/$(2)/tb_$(2).cpp
endef
$(eval $(call ECP5_TB_RULE,mul_ecp5,mul,))
# and with no fabric tile at all (LUT_TILE_MAX 0: every corner in a block,
# as csgrt_spawn's gradient products are built)
$(eval $(call ECP5_TB_RULE,mul_ecp5_t0,mul,-DCSGRT_LUT_TILE_MAX=0))
# and with the larger fabric tiles of tools/synth.sh --lut-tile-max 81
$(eval $(call ECP5_TB_RULE,mul_ecp5_t81,mul,-DCSGRT_LUT_TILE_MAX=81))
# and with a register behind each tile (csgrt_mul TILE_REG), fabric tiles of 81 too
$(eval $(call ECP5_TB_RULE,mul_ecp5_treg,mul,-DCSGRT_LUT_TILE_MAX=81 -GTILE_REG=1 -CFLAGS -DMUL_TILE_REG=1))
# the time-shared multiplier with the tile registers (two beats still)
$(eval $(call ECP5_TB_RULE,mul_vec_treg,mul_vec,-GTILE_REG=1))
# with the operand register as well (three beats), and with neither (two;
# build/tb/mul_vec has the operand register alone, csgrt_mul_vec's default)
$(eval $(call ECP5_TB_RULE,mul_vec_oreg,mul_vec,-GTILE_REG=1 -GOP_REG=1 -CFLAGS -DMUL_VEC_BEATS=3))
$(eval $(call ECP5_TB_RULE,mul_vec_noop,mul_vec,-GOP_REG=0))

.PHONY: tb lint-rtl
tb: $(TB_BINS)

# Lint every module at its default parameters, the intersection unit also
# at every coordinate width the model supports at the ends and the default;
# then synthesise each with yosys and assert a clean netlist.
LINT_MODULES := $(basename $(notdir $(TB_RTL)))
LINT_TOP_BITS := 12 16 24 32
# Lint every module at its default parameters and csgrt_top at each width
# and with two lanes; csgrt_spawn also at each width without each of its
# effect units (its generate branches); then synthesise csgrt_top (which
# contains every block) with yosys and assert a clean netlist without latches.
LINT_SPAWN_FX := "-GREFRACTION=0" "-GREFLECTION=0 -GREFRACTION=0" "-GREFLECTION=0" "-GSHADOWS=0" \
                 "-GSHADOWS=0 -GREFRACTION=0"
lint-rtl:
	@mkdir -p $(BUILD)   # the yosys logs below go there (a fresh clone has no build/)
	@set -e; for m in $(LINT_MODULES); do \
	    echo "verilator lint $$m"; \
	    $(VERILATOR) --lint-only -Wall -y rtl -y tb/ecp5 --top-module $$m rtl/$$m.v; \
	done; \
	for b in $(LINT_TOP_BITS); do \
	    echo "verilator lint csgrt_top BITS=$$b"; \
	    $(VERILATOR) --lint-only -Wall -y rtl --top-module csgrt_top -GBITS=$$b rtl/csgrt_top.v; \
	done; \
	for b in $(LINT_TOP_BITS); do \
	    echo "verilator lint csgrt_top BITS=$$b CSGRT_ECP5_DSP (MULT18X18D tiles)"; \
	    $(VERILATOR) --lint-only -Wall -DCSGRT_ECP5_DSP -y rtl -y tb/ecp5 --top-module csgrt_top -GBITS=$$b \
	        -GSHADOWS=1 -GREFLECTION=1 -GREFRACTION=1 rtl/csgrt_top.v; \
	done; \
	echo "verilator lint csgrt_top NUM_UNITS=2"; \
	$(VERILATOR) --lint-only -Wall -y rtl --top-module csgrt_top -GNUM_UNITS=2 rtl/csgrt_top.v; \
	echo "verilator lint csgrt_top NUM_UNITS=2 SHADOWS=1 REFLECTION=1"; \
	$(VERILATOR) --lint-only -Wall -y rtl --top-module csgrt_top -GNUM_UNITS=2 -GSHADOWS=1 -GREFLECTION=1 rtl/csgrt_top.v; \
	for fx in "-GSHADOWS=1 -GREFLECTION=1 -GREFRACTION=1" "-GSHADOWS=1 -GREFLECTION=1" "-GSHADOWS=1" "-GREFLECTION=1" "-GREFRACTION=1" \
	          "-GSPECULAR=0" "-GSHADOWS=1 -GREFLECTION=1 -GREFRACTION=1 -GSPECULAR=0" \
	          "-GSHARE_II=1" "-GSHARE_II=1 -GSPECULAR=0" "-GSHARE_II=1 -GSHADOWS=1 -GREFLECTION=1 -GREFRACTION=1" \
	          "-GISECT_II=3 -GSHADOWS=1 -GREFLECTION=1 -GREFRACTION=1" \
	          "-GSHADOWS=1 -GREFLECTION=1 -GCONTEXTS=16" "-GSHADOWS=1 -GREFLECTION=1 -GREFRACTION=1 -GCONTEXTS=32" \
	          "-GSHADOWS=1 -GREFLECTION=1 -GREFRACTION=1 -GMAX_LIGHTS=1" "-GSHADOWS=1 -GREFLECTION=1 -GMAX_LIGHTS=2"; do for b in $(LINT_TOP_BITS); do \
	    echo "verilator lint csgrt_top BITS=$$b $$fx"; \
	    $(VERILATOR) --lint-only -Wall -y rtl --top-module csgrt_top -GBITS=$$b $$fx rtl/csgrt_top.v; \
	done; done; \
	for fx in $(LINT_SPAWN_FX); do for b in $(LINT_TOP_BITS); do \
	    echo "verilator lint csgrt_spawn BITS=$$b $$fx"; \
	    $(VERILATOR) --lint-only -Wall -y rtl --top-module csgrt_spawn -GBITS=$$b $$fx rtl/csgrt_spawn.v; \
	done; done; \
	for fx in "REFRACTION 0" "REFLECTION 0 -set REFRACTION 0"; do \
	    echo "yosys proc csgrt_spawn $$fx (no latches)"; \
	    $(YOSYS) -q -l $(BUILD)/yosys_lint_spawn.log -p "read_verilog $(TB_RTL); chparam -set $$fx csgrt_spawn; \
	        hierarchy -top csgrt_spawn; proc; check -assert; \
	        select -assert-none t:\$$dlatch t:\$$adlatch" > /dev/null; \
	done; \
	echo "yosys proc csgrt_top SHADOWS=1 REFLECTION=1 (the ray tree: no latches)"; \
	$(YOSYS) -q -l $(BUILD)/yosys_lint_fx.log -p "read_verilog $(TB_RTL); chparam -set SHADOWS 1 -set REFLECTION 1 -set REFRACTION 1 csgrt_top; \
	    hierarchy -top csgrt_top; proc; check -assert; \
	    select -assert-none t:\$$dlatch t:\$$adlatch" > /dev/null; \
	echo "yosys synth csgrt_top (BITS=24; a few minutes)"; \
	$(YOSYS) -q -l $(BUILD)/yosys_lint.log -p "read_verilog $(TB_RTL); synth -top csgrt_top; check -assert; \
	    select -assert-none t:\$$dlatch t:\$$adlatch t:\$$_DLATCH_*" > /dev/null; \
	echo "lint-rtl: clean (no warnings, no latches; yosys log in $(BUILD)/yosys_lint.log)"
