`default_nettype none
// csgrt_scene_loader — takes the binary scene image (docs/scene-image.md) as
// a stream of 32-bit words, exactly the words `csgrt compile` writes, and
// decodes it into the configuration the tracer runs on: camera, lights,
// materials, leaf coefficients, candidate list and classification tree.
// Decoding happens as the words arrive, so no copy of the image is kept.
//
// Handshake: word_valid_i / word_ready_o (always ready: one word per clock).
// loaded_o rises after the last word (header TOTAL) and stays high until
// reset; error_o then holds a code instead when the image does not fit this
// configuration (the host reports it):
//   1 bad magic or version     2 BITS differs from the parameter
//   3 more than MAX_LEAVES     4 more than MAX_LIGHTS or MAX_MATERIALS
//   5 tree height differs from TREE_HEIGHT, or no tree section
// Memories (leaf coefficients, leaf slots, materials) have registered read
// ports for the dispatcher and the shading lookup.
module csgrt_scene_loader #(
    parameter BITS          = 24,    // coordinate width B
    parameter MAX_LEAVES    = 64,    // leaf half-spaces
    parameter TREE_HEIGHT   = 8,     // classification tree height
    parameter MAX_LIGHTS    = 8,
    parameter MAX_MATERIALS = 255,   // materials besides air
    // derived
    parameter LEAF_BITS     = $clog2(MAX_LEAVES),
    parameter SLOTS         = 1 << TREE_HEIGHT
) (
    input  wire                       clk_i,
    input  wire                       rst_ni,
    // the scene image
    input  wire                       word_valid_i,
    output wire                       word_ready_o,
    input  wire [31:0]                word_i,
    output reg                        loaded_o,
    output reg  [3:0]                 error_o,
    // frame
    output reg  [11:0]                width_o,
    output reg  [11:0]                height_o,
    output reg  [LEAF_BITS:0]         num_leaves_o,
    output reg  [3:0]                 num_lights_o,
    output reg  [7:0]                 max_trace_o,      // global_settings max_trace_level
    // camera (docs/numerics.md section 2)
    output reg  [3*BITS-1:0]          cam_origin_o,
    output reg  [3*64-1:0]            cam_base_o,
    output reg  [3*64-1:0]            cam_dx_o,
    output reg  [3*64-1:0]            cam_dy_o,
    output reg  [3*16-1:0]            background_o,
    // lights
    output reg  [MAX_LIGHTS*3*BITS-1:0] light_pos_o,
    output reg  [MAX_LIGHTS*3*16-1:0]   light_col_o,
    output reg  [MAX_LIGHTS-1:0]        light_shadowless_o,   // flags bit 0: no shadow rays to it
    // classification tree: operator per heap position, material per slot
    output reg  [2*SLOTS-1:0]         node_op_o,
    output reg  [8*SLOTS-1:0]         slot_material_o,
    output reg  [SLOTS-1:0]           slot_used_o,
    // leaf memory read port A (dispatcher): coefficients, material, slot
    input  wire [LEAF_BITS-1:0]       leaf_a_addr_i,
    output reg  [10*BITS-1:0]         leaf_a_coef_o,
    output reg  [TREE_HEIGHT-1:0]     leaf_a_slot_o,
    // leaf memory read port B (shading lookup)
    input  wire [LEAF_BITS-1:0]       leaf_b_addr_i,
    output reg  [10*BITS-1:0]         leaf_b_coef_o,
    // material memory read port (material index 1..; 0 reads entry 0)
    input  wire [7:0]                 mat_addr_i,
    output reg  [9*16+10-1:0]         mat_o,       // the record below
    output reg  [1:0]                 mat_want_o,  // the same material's {filter != 0, reflection != 0}
    // refraction: leaf memory read port C (the look-ahead's quadric test),
    // the index of refraction of two materials (ior_of: air 1 << 12) and a
    // bit per material that lets rays through (is_transparent: air, or
    // filter > 0)
    input  wire [LEAF_BITS-1:0]       leaf_c_addr_i,
    output reg  [10*BITS-1:0]         leaf_c_coef_o,
    input  wire [7:0]                 ior_a_addr_i,
    output reg  [15:0]                ior_a_o,
    input  wire [7:0]                 ior_b_addr_i,
    output reg  [15:0]                ior_b_o,
    output reg  [(1<<8)-1:0]          mat_clear_o
);
    // Material record layout on mat_o (16-bit fields, 12 fraction bits):
    //   [15:0] r  [31:16] g  [47:32] b  [63:48] ambient  [79:64] diffuse
    //   [95:80] phong  [111:96] reflection  [121:112] phong_size
    //   [137:122] filter  [153:138] ior
    localparam MAT_W = 9 * 16 + 10;

    // header word indices (model/scene_image.h, enum SceneHeader)
    // (5 PROGRAM and 9 STACK are not needed by this configuration)
    localparam H_MAGIC = 0, H_VERSION = 1, H_BITS = 2, H_SIZE = 3, H_LEAVES = 4,
               H_MATERIALS = 6, H_LIGHTS = 7, H_MAX_TRACE = 8, H_OFF_CAMERA = 10,
               H_OFF_LIGHTS = 11, H_OFF_MATERIALS = 12, H_OFF_LEAVES = 13, H_OFF_PROGRAM = 14,
               H_OFF_TREE = 15, H_TOTAL = 16, HEADER_WORDS = 17;
    localparam [31:0] MAGIC = 32'h52475343, VERSION = 32'd2;
    localparam LEAF_WORDS = 11, MATERIAL_WORDS = 10, LIGHT_WORDS = 7;

    assign word_ready_o = 1'b1;

    reg [31:0] idx_q;                         // index of the word arriving now
    // idx_q's header words as a one-hot code (hdr_q[k]: idx_q == k < HEADER_WORDS),
    // shifted with idx_q's step: the header's case over idx_q's 32 bits
    // decided the header registers' enables (tools/logic_depth.py 12.45 ns)
    reg [HEADER_WORDS-1:0] hdr_q;
    reg [31:0] off_camera_q, off_lights_q, off_materials_q, off_leaves_q, off_program_q, off_tree_q, total_q;

    // memories
    reg [10*BITS-1:0]     leaf_coef_mem [0:MAX_LEAVES-1];
    reg [TREE_HEIGHT-1:0] leaf_slot_mem [0:MAX_LEAVES-1];
    reg [7:0]             leaf_mat_q    [0:MAX_LEAVES-1];
    // a material's record (mat_o) and, above it, its {filter != 0,
    // reflection != 0} (mat_want_o), tested when it is written: the ray
    // tree decides a hit's reflected and transmitted children from them.
    // (The zero tests after the block-RAM read, 5.8 ns clock to output,
    // were once the routed effects build's critical path. The bits then
    // had a LUT RAM of their own, 256 entries in 16 banks: its read and
    // 16-to-1 choice behind the shown material's address became the
    // critical path of 9f2f1a7's routed build, 88.25 MHz, the walker's
    // record -> the material address -> the LUT RAM -> mat_want_o. In the
    // record's block RAM the two bits cost no block: 154 + 2 bits fit the
    // same five 36-bit columns.)
    reg [MAT_W+1:0]       mat_mem       [0:MAX_MATERIALS];
    reg [15:0]            ior_mem       [0:MAX_MATERIALS];   // the iors again: two more read ports

    // per-section position: item and field counters instead of divisions
    reg [31:0]            item_q;
    reg [3:0]             field_q;
    reg [10*BITS-1:0]     coef_acc_q;     // the leaf being assembled
    reg [MAT_W-11:0]      mat_acc_q;      // the material being assembled: fields without phong_size
    // its two tests, stored when it is written: it lets light through
    // (filter > 0: mat_clear_o, and the ray tree's transmitted child) and
    // it reflects (the ray tree's reflected child)
    wire                  mat_acc_clear    = mat_acc_q[112 +: 16] != 16'd0;
    wire                  mat_acc_reflects = mat_acc_q[96 +: 16] != 16'd0;

    // Three stages. Stage 0 takes the arriving word: it parses the header
    // and works out where the word belongs from its index (32-bit compares
    // and differences with the section offsets: carry chains). Stage 1,
    // a clock later, writes it from those registered answers, or, for the
    // camera, lights, materials and leaves, decodes where stage 2 writes
    // it (below). In one stage, the compares' carry chains led straight
    // into the enables of the wide configuration registers (the
    // classification tree's operators, thousands of flip-flops away:
    // tools/logic_depth.py). loaded_o rises when stage 2 has passed the
    // last word.
    wire in_camera0    = idx_q >= off_camera_q    && idx_q < off_lights_q;
    wire in_lights0    = idx_q >= off_lights_q    && idx_q < off_materials_q;
    wire in_materials0 = idx_q >= off_materials_q && idx_q < off_leaves_q;
    wire in_leaves0    = idx_q >= off_leaves_q    && idx_q < off_program_q;
    wire in_tree0      = idx_q >= off_tree_q      && idx_q < total_q;
    wire [31:0] tree_r0    = idx_q - off_tree_q;
    wire [31:0] tree_leaf0 = tree_r0 - SLOTS - 1;
    reg         s1_valid_q, s1_last_q, done0_q;   // done0_q: stage 0 has taken the last word
    reg  [31:0] s1_w_q;
    reg         in_lights_q, in_materials_q, in_leaves_q, in_tree_q, section_start_q;
    reg         tree_first_q, tree_op_q, tree_leaf_ok_q;   // tree_r == 0, 1 <= tree_r <= SLOTS, tree_leaf < MAX_LEAVES
    reg  [TREE_HEIGHT-1:0] op_pos_q;                      // heap position - 1 (1 <= tree_r <= SLOTS)
    reg  [LEAF_BITS-1:0]   tree_leaf_q;
    // The word's checks, made in stage 0 and applied to error_o in stage 1:
    // a header word's code (s1_e_q, below; none: fine) and the tree's height
    // (s1_bad_height_q). Made on stage 1's word, the height's 32-bit compare
    // hung on s1_w_q, whose loads (every configuration register) spread
    // across the die, and ran on into error_o: the routed effects build's
    // critical path (docs/fpga.md). A load is not timing-critical; its
    // registers are.
    // The header code as one flag per code (s1_e_q[c-1]: code c), each the
    // test of its own header word: the words are one per position, so at
    // most one flag is set, and the code is their OR (two LUT levels in
    // stage 1). The code itself as the register took the six tests as a
    // priority chain, 7 LUT levels from the word into s1_err_q (tools/
    // logic_depth.py 11.10 ns, 62 endpoints over 10 ns on aaa564b's netlist).
    reg  [3:0]             s1_e_q;
    wire [3:0]             s1_err = s1_e_q[3] ? 4'd4 : {2'b0, s1_e_q[1] | s1_e_q[2], s1_e_q[0] | s1_e_q[2]};
    reg                    s1_bad_height_q;
    reg                    s1_max_trace_q, s1_big_q;   // the trace depth's header word, and over 255
    // Stage 2 writes the camera, the lights, the materials, the leaves and
    // the tree's operators and slot materials, from enables (and for the
    // memories an address) decoded in stage 1:
    // one register per word position. Decoded and written in stage 1, an
    // item's 32-bit compare (the item < MAX_LIGHTS, MAX_MATERIALS or
    // MAX_LEAVES: a carry chain behind section_start_q's mux) led into the
    // write enables across the die: the light registers' was the routed
    // f8d2add build's critical path, the leaf materials' that of 2a28a4c
    // (docs/fpga.md). A material's or leaf's record is written from
    // mat_acc_q or coef_acc_q a clock after its last word: in that clock
    // stage 1 writes only the first field of the next one, which the
    // record does not read back until the clock after. loaded_o rises in
    // stage 2 too, with the last word's stage-2 clock, so everything is
    // written when it rises whatever the sections' order.
    localparam CAM_WORDS = 24;
    reg  [31:0]                 s2_w_q;
    reg                         s2_last_q;
    reg  [CAM_WORDS-1:0]        s2_cam_we_q;                  // camera word k
    reg  [MAX_LIGHTS*LIGHT_WORDS-1:0] s2_light_we_q;          // light j, field f at j*LIGHT_WORDS + f
    reg                         s2_mat_we_q;                  // a material's last word: its record
    reg  [7:0]                  s2_mat_addr_q;                // its entry (material index: item + 1)
    reg                         s2_leaf_we_q;                 // a leaf's last word: its coefficients and material
    // the tree's operator at heap position j + 1 (s2_op_we_q[j]) and slot
    // j's material (s2_slot_we_q[j], the material read in stage 1:
    // s2_slot_mat_q). Written in stage 1, their enables' decode (the word's
    // slot or the operator's position, and the section's flags) ran on into
    // the class trees' configuration registers in every lane, across the
    // die (tools/logic_depth.py: the load's paths into node_op_i).
    reg  [SLOTS-1:0]            s2_op_we_q, s2_slot_we_q;
    reg  [7:0]                  s2_slot_mat_q;
    reg  [LEAF_BITS-1:0]        s2_leaf_addr_q;
    // The camera word's position, decoded in stage 0 (s1_cam_we_q[k]: the
    // word is camera word k), so that stage 1 only passes the bits on.
    // Decoded in stage 1 from idx_q - off_camera_q, the difference's
    // 32-bit compares led into s2_cam_we_q with the camera registers' route
    // across the die behind them: the routed critical path of 3866833's
    // build (11.97 ns, 5.02 ns of it the route). Now that route is
    // register to register.
    wire [31:0] cam_r0 = idx_q - off_camera_q;
    reg  [CAM_WORDS-1:0] s1_cam_we_q;
    wire [3:0] section_size = in_lights_q ? LIGHT_WORDS[3:0] : in_materials_q ? MATERIAL_WORDS[3:0] : LEAF_WORDS[3:0];
    wire [31:0] w = s1_w_q;   // stage 1's word
    // this word's field within the current section (its item: item_q, or 0 at a start)
    wire [3:0]  f_now  = section_start_q ? 4'd0 : field_q;

    // Writes into the wide configuration registers go through loops over
    // constant positions (one compare each) rather than part-selects with a
    // computed 32-bit index, which synthesise to barrel shifters thousands
    // of LUTs wide (docs/fpga.md); the positions written are the same.
    wire [31:0] op32   = {{(32-TREE_HEIGHT){1'b0}}, op_pos_q};
    wire [31:0] slot32 = {{(32-TREE_HEIGHT){1'b0}}, w[TREE_HEIGHT-1:0]};
    wire [31:0] f32    = {28'd0, f_now};

    integer k, j, f;

    always @(posedge clk_i) begin
        // stage 2's enables last a clock (stage 1 sets them), reset or not
        s2_cam_we_q   <= {CAM_WORDS{1'b0}};
        s2_op_we_q    <= {SLOTS{1'b0}};
        s2_slot_we_q  <= {SLOTS{1'b0}};
        s2_light_we_q <= {(MAX_LIGHTS*LIGHT_WORDS){1'b0}};
        s2_mat_we_q   <= 1'b0;
        s2_leaf_we_q  <= 1'b0;
        if (!rst_ni) begin
            idx_q        <= 32'd0;
            hdr_q        <= {{(HEADER_WORDS-1){1'b0}}, 1'b1};
            done0_q      <= 1'b0;
            s1_valid_q   <= 1'b0;
            s2_last_q    <= 1'b0;
            loaded_o     <= 1'b0;
            error_o      <= 4'd0;
            slot_used_o  <= {SLOTS{1'b0}};
            mat_clear_o  <= {{255{1'b0}}, 1'b1};   // air lets rays through; materials as they load
            num_lights_o <= 4'd0;
            light_shadowless_o <= {MAX_LIGHTS{1'b0}};
            // until the header arrives every section lies beyond any index
            off_camera_q <= 32'hffff_ffff; off_lights_q <= 32'hffff_ffff; off_materials_q <= 32'hffff_ffff;
            off_leaves_q <= 32'hffff_ffff; off_program_q <= 32'hffff_ffff; off_tree_q <= 32'hffff_ffff;
            total_q      <= 32'hffff_ffff;
            item_q       <= 32'd0;
            field_q      <= 4'd0;
        end else begin
            s1_valid_q <= 1'b0;
            s2_last_q  <= s1_valid_q && s1_last_q;
            if (word_valid_i && !done0_q) begin
                // ---- stage 0: the index, the header, where the word belongs
                idx_q <= idx_q + 32'd1;
                hdr_q <= hdr_q << 1;
                if (idx_q + 32'd1 == total_q) done0_q <= 1'b1;
                s1_valid_q      <= 1'b1;
                s1_last_q       <= idx_q + 32'd1 == total_q;
                s1_w_q          <= word_i;
                for (j = 0; j < CAM_WORDS; j = j + 1)
                    s1_cam_we_q[j] <= in_camera0 && cam_r0 == j;
                in_lights_q     <= in_lights0;
                in_materials_q  <= in_materials0;
                in_leaves_q     <= in_leaves0;
                in_tree_q       <= in_tree0;
                // a section starts: its counters restart
                section_start_q <= (idx_q == off_lights_q) || (idx_q == off_materials_q) || (idx_q == off_leaves_q);
                tree_first_q    <= tree_r0 == 32'd0;
                tree_op_q       <= tree_r0 != 32'd0 && tree_r0 <= SLOTS;
                tree_leaf_ok_q  <= tree_leaf0 < MAX_LEAVES;
                op_pos_q        <= tree_r0[TREE_HEIGHT-1:0] - 1'b1;
                tree_leaf_q     <= tree_leaf0[LEAF_BITS-1:0];
                s1_e_q          <= 4'd0;
                s1_bad_height_q <= word_i != TREE_HEIGHT;
                // the header (the other header words, program length,
                // trace depth and stack, are not needed here)
                s1_e_q[0] <= (hdr_q[H_MAGIC] && word_i != MAGIC) || (hdr_q[H_VERSION] && word_i != VERSION);
                s1_e_q[1] <= hdr_q[H_BITS] && word_i != BITS;
                if (hdr_q[H_SIZE]) begin
                    width_o  <= word_i[11:0];
                    height_o <= word_i[27:16];
                end
                if (hdr_q[H_LEAVES]) begin
                    s1_e_q[2] <= word_i > MAX_LEAVES;
                    num_leaves_o <= word_i[LEAF_BITS:0];
                end
                s1_e_q[3] <= (hdr_q[H_MATERIALS] && word_i > MAX_MATERIALS + 1) || (hdr_q[H_LIGHTS] && word_i > MAX_LIGHTS);
                if (hdr_q[H_LIGHTS]) begin
                    num_lights_o <= word_i[3:0];
                end
                // the trace depth, saturated at 255, is written in stage 1
                // from these (the 24-bit test and the choice in front of its
                // enable were a 4-level path from the word's valid bit,
                // tools/logic_depth.py 10.98 ns)
                s1_max_trace_q  <= hdr_q[H_MAX_TRACE];
                s1_big_q        <= word_i[31:8] != 24'd0;
                if (hdr_q[H_OFF_CAMERA])    off_camera_q    <= word_i;
                if (hdr_q[H_OFF_LIGHTS])    off_lights_q    <= word_i;
                if (hdr_q[H_OFF_MATERIALS]) off_materials_q <= word_i;
                if (hdr_q[H_OFF_LEAVES])    off_leaves_q    <= word_i;
                if (hdr_q[H_OFF_PROGRAM])   off_program_q   <= word_i;
                if (hdr_q[H_OFF_TREE])      off_tree_q      <= word_i;
                if (hdr_q[H_TOTAL])         total_q         <= word_i;
            end

            if (s1_valid_q) begin
                // ---- stage 1: the sections' writes
                if (s1_e_q != 4'd0) error_o <= s1_err;   // a header word's check
                if (s1_max_trace_q) max_trace_o <= s1_big_q ? 8'd255 : w[7:0];

                // ---- camera: origin (3), base/dx/dy (3 x 2 words each), background (3): stage 2's enables
                s2_cam_we_q <= s1_cam_we_q;

                // ---- lights, materials, leaves: item / field counters
                if (in_lights_q || in_materials_q || in_leaves_q) begin
                    if (section_start_q || field_q + 4'd1 == section_size) begin
                        field_q <= section_start_q ? 4'd1 : 4'd0;
                        item_q  <= section_start_q ? 32'd0 : item_q + 32'd1;
                    end else begin
                        field_q <= field_q + 4'd1;
                    end
                end
                // lights: stage 2's enables (f_now < LIGHT_WORDS = 7 here: the
                // field counter wraps at the section size; an item at or past
                // MAX_LIGHTS matches no j and is not written)
                // (At a section's start the word is item 0's field 0: the
                // compares are of item_q and field_q themselves, the start
                // choosing after them; through it_now and f32 the start's
                // 69 loads ran into 32-bit compares, 7 LUT levels to these
                // enables, tools/logic_depth.py 12.08 ns on 3599434's netlist.)
                if (in_lights_q)
                    for (j = 0; j < MAX_LIGHTS; j = j + 1)
                        for (f = 0; f < LIGHT_WORDS; f = f + 1)
                            if (section_start_q ? (j == 0 && f == 0) : (item_q == j && {28'd0, field_q} == f))
                                s2_light_we_q[j*LIGHT_WORDS + f] <= 1'b1;
                if (in_materials_q) begin
                    // words: r g b filter ambient diffuse phong reflection ior phong_size
                    case (f_now)
                        4'd0: mat_acc_q[0  +: 16] <= w[15:0];
                        4'd1: mat_acc_q[16 +: 16] <= w[15:0];
                        4'd2: mat_acc_q[32 +: 16] <= w[15:0];
                        4'd4: mat_acc_q[48 +: 16] <= w[15:0];
                        4'd5: mat_acc_q[64 +: 16] <= w[15:0];
                        4'd6: mat_acc_q[80 +: 16] <= w[15:0];
                        4'd7: mat_acc_q[96 +: 16] <= w[15:0];
                        4'd3: mat_acc_q[112 +: 16] <= w[15:0];   // filter
                        4'd8: mat_acc_q[128 +: 16] <= w[15:0];   // ior
                        4'd9: begin   // the record: stage 2 (field 9 is not a start: item_q is the item)
                                  s2_mat_we_q   <= item_q < MAX_MATERIALS;
                                  s2_mat_addr_q <= item_q[7:0] + 8'd1;
                              end
                        default: ;
                    endcase
                end
                if (in_leaves_q) begin
                    if (f_now < 10) begin
                        for (f = 0; f < 10; f = f + 1)
                            if (f32 == f) coef_acc_q[f * BITS +: BITS] <= w[BITS-1:0];
                    end else begin   // the leaf: stage 2 (field 10 is not a start: item_q is the item)
                        s2_leaf_we_q   <= item_q < MAX_LEAVES;
                        s2_leaf_addr_q <= item_q[LEAF_BITS-1:0];
                    end
                end

                // ---- tree: height, 2^H operators, one slot per leaf
                // (the operators and the slots' materials: stage 2's enables)
                if (in_tree_q) begin
                    if (tree_first_q) begin
                        if (s1_bad_height_q) error_o <= 4'd5;
                    end else if (tree_op_q) begin
                        for (j = 0; j < SLOTS; j = j + 1)
                            if (op32 == j) s2_op_we_q[j] <= 1'b1;
                    end else if (tree_leaf_ok_q) begin
                        leaf_slot_mem[tree_leaf_q] <= w[TREE_HEIGHT-1:0];
                        for (j = 0; j < SLOTS; j = j + 1)
                            if (slot32 == j) s2_slot_we_q[j] <= 1'b1;
                    end
                end
                s2_slot_mat_q <= leaf_mat_q[tree_leaf_q];
            end

            // ---- stage 2: camera, lights, materials, leaves, and loaded_o
            s2_w_q <= w;
            if (s2_last_q) loaded_o <= 1'b1;
            if (s2_mat_we_q) begin
                // the record (its layout: mat_o, above); phong_size is this last word
                mat_mem[s2_mat_addr_q] <= {mat_acc_clear, mat_acc_reflects,
                                           mat_acc_q[128 +: 16], mat_acc_q[112 +: 16], s2_w_q[9:0], mat_acc_q[111:0]};
                ior_mem[s2_mat_addr_q] <= mat_acc_q[128 +: 16];
                mat_clear_o[s2_mat_addr_q]  <= mat_acc_clear;
            end
            if (s2_leaf_we_q) begin
                leaf_coef_mem[s2_leaf_addr_q] <= coef_acc_q;
                leaf_mat_q[s2_leaf_addr_q]    <= s2_w_q[7:0];
            end
            for (j = 0; j < SLOTS; j = j + 1) begin
                if (s2_op_we_q[j]) node_op_o[j * 2 +: 2] <= s2_w_q[1:0];
                if (s2_slot_we_q[j]) begin
                    slot_material_o[j * 8 +: 8] <= s2_slot_mat_q;
                    slot_used_o[j] <= 1'b1;
                end
            end
            for (j = 0; j < 3; j = j + 1) begin
                if (s2_cam_we_q[j])      cam_origin_o[j*BITS +: BITS] <= s2_w_q[BITS-1:0];
                if (s2_cam_we_q[21 + j]) background_o[j*16 +: 16]     <= s2_w_q[15:0];
            end
            for (j = 0; j < 6; j = j + 1) begin
                if (s2_cam_we_q[3 + j])  cam_base_o[j*32 +: 32] <= s2_w_q;
                if (s2_cam_we_q[9 + j])  cam_dx_o[j*32 +: 32]   <= s2_w_q;
                if (s2_cam_we_q[15 + j]) cam_dy_o[j*32 +: 32]   <= s2_w_q;
            end
            for (j = 0; j < MAX_LIGHTS; j = j + 1) begin
                for (f = 0; f < 3; f = f + 1)
                    if (s2_light_we_q[j*LIGHT_WORDS + f]) light_pos_o[(j*3 + f) * BITS +: BITS] <= s2_w_q[BITS-1:0];
                for (f = 3; f < 6; f = f + 1)
                    if (s2_light_we_q[j*LIGHT_WORDS + f]) light_col_o[(j*3 + f - 3) * 16 +: 16] <= s2_w_q[15:0];
                if (s2_light_we_q[j*LIGHT_WORDS + 6]) light_shadowless_o[j] <= s2_w_q[0];
            end
        end
    end

    // registered read ports
    always @(posedge clk_i) begin
        leaf_a_coef_o <= leaf_coef_mem[leaf_a_addr_i];
        leaf_a_slot_o <= leaf_slot_mem[leaf_a_addr_i];
        leaf_b_coef_o <= leaf_coef_mem[leaf_b_addr_i];
        {mat_want_o, mat_o} <= mat_mem[mat_addr_i];
        leaf_c_coef_o <= leaf_coef_mem[leaf_c_addr_i];
        ior_a_o       <= (ior_a_addr_i == 8'd0) ? 16'd4096 : ior_mem[ior_a_addr_i];
        ior_b_o       <= (ior_b_addr_i == 8'd0) ? 16'd4096 : ior_mem[ior_b_addr_i];
    end

    initial begin
        for (k = 0; k <= MAX_MATERIALS; k = k + 1) begin
            mat_mem[k] = {(MAT_W+2){1'b0}};
            ior_mem[k] = 16'd0;
        end
    end
    csgrt_check_same #(.WIDTH(HEADER_WORDS), .WHAT("hdr_q (the header word's one-hot index)")) u_check_hdr (
        .clk_i, .rst_ni, .copy_i(hdr_q),
        .orig_i(idx_q < HEADER_WORDS ? {{(HEADER_WORDS-1){1'b0}}, 1'b1} << idx_q : {HEADER_WORDS{1'b0}}));
endmodule
`default_nettype wire
