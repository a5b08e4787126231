// specular_device_ports.vh: the connections of the device's pins 17-35, its configuration
// inputs and the observation outputs both variants have, to the signals of
// specular_device_bench.vh. `include it inside the bench's instance of the device, after
// the connections of the variant's own observation outputs (a trailing comma).
    .pin17_cos(pin17_cos), .pin18_n(pin18_n), .pin19_h(pin19_h), .pin20_a(pin20_a),
    .pin21_r(pin21_r), .pin22_g(pin22_g), .pin23_b(pin23_b),
    .pin24_r(pin24_r), .pin25_g(pin25_g), .pin26_b(pin26_b),
    .pin27_start(pin27_start), .pin28_clk(pin28_clk), .pin29_reset_n(pin29_reset_n),
    .pin30_load_n(pin30_load_n), .pin31_load_r(pin31_load_r), .pin32_load_g(pin32_load_g),
    .pin33_load_b(pin33_load_b), .pin34_carry(pin34_carry), .pin35_done(pin35_done),
    .cfg_literal(cfg_literal), .cfg_rom38_bank(cfg_rom38_bank),
    .obs_select36(obs_select36), .obs_write37(obs_write37), .obs_reg1_q(obs_reg1_q),
    .obs_reg9_q(obs_reg9_q), .obs_rom38_k(obs_rom38_k), .obs_mul39_norm(obs_mul39_norm)
