`default_nettype none
// tb_shade — Verilator top for tb_shade.cpp: csgrt_shade (MAX_LIGHTS 8) at
// BITS 12, 16, 24 and 32, one clock each so that only the instance under
// test is evaluated. BITS 16 and 32 are time-shared (II = 3: a pixel or light
// item every third clock, a third of the multipliers), 12 and 24 are not
// (tb_shade.cpp's kShadeII says the same).
module tb_shade (
    input  wire              b12_clk_i,
    input  wire              b12_rst_ni,
    input  wire [3:0]        b12_num_lights_i,
    input  wire [287:0]  b12_light_pos_i,
    input  wire [383:0]      b12_light_color_i,
    input  wire [47:0]       b12_background_i,
    input  wire              b12_valid_i,
    output wire              b12_ready_o,
    input  wire [11:0]       b12_x_i,
    input  wire [11:0]       b12_y_i,
    input  wire              b12_hit_i,
    input  wire [10:0]  b12_t_i,
    input  wire [35:0]  b12_o_i,
    input  wire [35:0]  b12_d_i,
    input  wire [119:0]  b12_coef_i,
    input  wire [47:0]       b12_rgb_i,
    input  wire [15:0]       b12_ambient_i,
    input  wire [15:0]       b12_diffuse_i,
    input  wire [15:0]       b12_phong_i,
    input  wire [9:0]        b12_phong_size_i,
    output wire              b12_valid_o,
    input  wire              b12_ready_i,
    output wire [11:0]       b12_x_o,
    output wire [11:0]       b12_y_o,
    output wire [7:0]        b12_r_o,
    output wire [7:0]        b12_g_o,
    output wire [7:0]        b12_b_o,
    input  wire              b16_clk_i,
    input  wire              b16_rst_ni,
    input  wire [3:0]        b16_num_lights_i,
    input  wire [383:0]  b16_light_pos_i,
    input  wire [383:0]      b16_light_color_i,
    input  wire [47:0]       b16_background_i,
    input  wire              b16_valid_i,
    output wire              b16_ready_o,
    input  wire [11:0]       b16_x_i,
    input  wire [11:0]       b16_y_i,
    input  wire              b16_hit_i,
    input  wire [14:0]  b16_t_i,
    input  wire [47:0]  b16_o_i,
    input  wire [47:0]  b16_d_i,
    input  wire [159:0]  b16_coef_i,
    input  wire [47:0]       b16_rgb_i,
    input  wire [15:0]       b16_ambient_i,
    input  wire [15:0]       b16_diffuse_i,
    input  wire [15:0]       b16_phong_i,
    input  wire [9:0]        b16_phong_size_i,
    output wire              b16_valid_o,
    input  wire              b16_ready_i,
    output wire [11:0]       b16_x_o,
    output wire [11:0]       b16_y_o,
    output wire [7:0]        b16_r_o,
    output wire [7:0]        b16_g_o,
    output wire [7:0]        b16_b_o,
    input  wire              b24_clk_i,
    input  wire              b24_rst_ni,
    input  wire [3:0]        b24_num_lights_i,
    input  wire [575:0]  b24_light_pos_i,
    input  wire [383:0]      b24_light_color_i,
    input  wire [47:0]       b24_background_i,
    input  wire              b24_valid_i,
    output wire              b24_ready_o,
    input  wire [11:0]       b24_x_i,
    input  wire [11:0]       b24_y_i,
    input  wire              b24_hit_i,
    input  wire [22:0]  b24_t_i,
    input  wire [71:0]  b24_o_i,
    input  wire [71:0]  b24_d_i,
    input  wire [239:0]  b24_coef_i,
    input  wire [47:0]       b24_rgb_i,
    input  wire [15:0]       b24_ambient_i,
    input  wire [15:0]       b24_diffuse_i,
    input  wire [15:0]       b24_phong_i,
    input  wire [9:0]        b24_phong_size_i,
    output wire              b24_valid_o,
    input  wire              b24_ready_i,
    output wire [11:0]       b24_x_o,
    output wire [11:0]       b24_y_o,
    output wire [7:0]        b24_r_o,
    output wire [7:0]        b24_g_o,
    output wire [7:0]        b24_b_o,
    input  wire              b32_clk_i,
    input  wire              b32_rst_ni,
    input  wire [3:0]        b32_num_lights_i,
    input  wire [767:0]  b32_light_pos_i,
    input  wire [383:0]      b32_light_color_i,
    input  wire [47:0]       b32_background_i,
    input  wire              b32_valid_i,
    output wire              b32_ready_o,
    input  wire [11:0]       b32_x_i,
    input  wire [11:0]       b32_y_i,
    input  wire              b32_hit_i,
    input  wire [30:0]  b32_t_i,
    input  wire [95:0]  b32_o_i,
    input  wire [95:0]  b32_d_i,
    input  wire [319:0]  b32_coef_i,
    input  wire [47:0]       b32_rgb_i,
    input  wire [15:0]       b32_ambient_i,
    input  wire [15:0]       b32_diffuse_i,
    input  wire [15:0]       b32_phong_i,
    input  wire [9:0]        b32_phong_size_i,
    output wire              b32_valid_o,
    input  wire              b32_ready_i,
    output wire [11:0]       b32_x_o,
    output wire [11:0]       b32_y_o,
    output wire [7:0]        b32_r_o,
    output wire [7:0]        b32_g_o,
    output wire [7:0]        b32_b_o
);

    csgrt_shade #(.BITS(12), .MAX_LIGHTS(8)) u_b12 (
        .clk_i(b12_clk_i), .rst_ni(b12_rst_ni),
        .num_lights_i(b12_num_lights_i), .light_pos_i(b12_light_pos_i), .light_color_i(b12_light_color_i),
        .background_i(b12_background_i),
        .s_valid_i(b12_valid_i), .s_ready_o(b12_ready_o), .s_x_i(b12_x_i), .s_y_i(b12_y_i), .s_hit_i(b12_hit_i),
        .s_t_i(b12_t_i), .s_o_i(b12_o_i), .s_d_i(b12_d_i), .s_coef_i(b12_coef_i), .s_rgb_i(b12_rgb_i),
        .s_ambient_i(b12_ambient_i), .s_diffuse_i(b12_diffuse_i), .s_phong_i(b12_phong_i),
        .s_phong_size_i(b12_phong_size_i),
        .m_valid_o(b12_valid_o), .m_ready_i(b12_ready_i), .m_x_o(b12_x_o), .m_y_o(b12_y_o),
        .m_r_o(b12_r_o), .m_g_o(b12_g_o), .m_b_o(b12_b_o),
        // the ray tree's outputs and light-colour port (LINEAR_OUT = EXT_LIGHT = 0): unused
        /* verilator lint_off PINCONNECTEMPTY */
        .m_local_o(), .m_spec_o(), .lc_tag_o(), .lc_k_o(),
        /* verilator lint_on PINCONNECTEMPTY */
        .lc_color_i(48'd0));

    csgrt_shade #(.BITS(16), .MAX_LIGHTS(8), .II(3)) u_b16 (
        .clk_i(b16_clk_i), .rst_ni(b16_rst_ni),
        .num_lights_i(b16_num_lights_i), .light_pos_i(b16_light_pos_i), .light_color_i(b16_light_color_i),
        .background_i(b16_background_i),
        .s_valid_i(b16_valid_i), .s_ready_o(b16_ready_o), .s_x_i(b16_x_i), .s_y_i(b16_y_i), .s_hit_i(b16_hit_i),
        .s_t_i(b16_t_i), .s_o_i(b16_o_i), .s_d_i(b16_d_i), .s_coef_i(b16_coef_i), .s_rgb_i(b16_rgb_i),
        .s_ambient_i(b16_ambient_i), .s_diffuse_i(b16_diffuse_i), .s_phong_i(b16_phong_i),
        .s_phong_size_i(b16_phong_size_i),
        .m_valid_o(b16_valid_o), .m_ready_i(b16_ready_i), .m_x_o(b16_x_o), .m_y_o(b16_y_o),
        .m_r_o(b16_r_o), .m_g_o(b16_g_o), .m_b_o(b16_b_o),
        // the ray tree's outputs and light-colour port (LINEAR_OUT = EXT_LIGHT = 0): unused
        /* verilator lint_off PINCONNECTEMPTY */
        .m_local_o(), .m_spec_o(), .lc_tag_o(), .lc_k_o(),
        /* verilator lint_on PINCONNECTEMPTY */
        .lc_color_i(48'd0));

    csgrt_shade #(.BITS(24), .MAX_LIGHTS(8)) u_b24 (
        .clk_i(b24_clk_i), .rst_ni(b24_rst_ni),
        .num_lights_i(b24_num_lights_i), .light_pos_i(b24_light_pos_i), .light_color_i(b24_light_color_i),
        .background_i(b24_background_i),
        .s_valid_i(b24_valid_i), .s_ready_o(b24_ready_o), .s_x_i(b24_x_i), .s_y_i(b24_y_i), .s_hit_i(b24_hit_i),
        .s_t_i(b24_t_i), .s_o_i(b24_o_i), .s_d_i(b24_d_i), .s_coef_i(b24_coef_i), .s_rgb_i(b24_rgb_i),
        .s_ambient_i(b24_ambient_i), .s_diffuse_i(b24_diffuse_i), .s_phong_i(b24_phong_i),
        .s_phong_size_i(b24_phong_size_i),
        .m_valid_o(b24_valid_o), .m_ready_i(b24_ready_i), .m_x_o(b24_x_o), .m_y_o(b24_y_o),
        .m_r_o(b24_r_o), .m_g_o(b24_g_o), .m_b_o(b24_b_o),
        // the ray tree's outputs and light-colour port (LINEAR_OUT = EXT_LIGHT = 0): unused
        /* verilator lint_off PINCONNECTEMPTY */
        .m_local_o(), .m_spec_o(), .lc_tag_o(), .lc_k_o(),
        /* verilator lint_on PINCONNECTEMPTY */
        .lc_color_i(48'd0));

    csgrt_shade #(.BITS(32), .MAX_LIGHTS(8), .II(3)) u_b32 (
        .clk_i(b32_clk_i), .rst_ni(b32_rst_ni),
        .num_lights_i(b32_num_lights_i), .light_pos_i(b32_light_pos_i), .light_color_i(b32_light_color_i),
        .background_i(b32_background_i),
        .s_valid_i(b32_valid_i), .s_ready_o(b32_ready_o), .s_x_i(b32_x_i), .s_y_i(b32_y_i), .s_hit_i(b32_hit_i),
        .s_t_i(b32_t_i), .s_o_i(b32_o_i), .s_d_i(b32_d_i), .s_coef_i(b32_coef_i), .s_rgb_i(b32_rgb_i),
        .s_ambient_i(b32_ambient_i), .s_diffuse_i(b32_diffuse_i), .s_phong_i(b32_phong_i),
        .s_phong_size_i(b32_phong_size_i),
        .m_valid_o(b32_valid_o), .m_ready_i(b32_ready_i), .m_x_o(b32_x_o), .m_y_o(b32_y_o),
        .m_r_o(b32_r_o), .m_g_o(b32_g_o), .m_b_o(b32_b_o),
        // the ray tree's outputs and light-colour port (LINEAR_OUT = EXT_LIGHT = 0): unused
        /* verilator lint_off PINCONNECTEMPTY */
        .m_local_o(), .m_spec_o(), .lc_tag_o(), .lc_k_o(),
        /* verilator lint_on PINCONNECTEMPTY */
        .lc_color_i(48'd0));
endmodule

`default_nettype wire
