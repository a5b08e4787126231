// specular_vectors.vh: the operations of `specular_tb --format csv` (Core's bits) for every
// bench that replays them (the device benches through specular_device_bench.vh, the bus
// benches specular_ip_axi_tb.v, specular_ip_axi_gate_tb.v, specular_soc_responses_tb.v).
// `include it inside the testbench module, after its parameters VECTORS (the CSV file) and
// MAX_VECTORS and its localparams TB_NAME (the bench's name, which its messages begin
// with) and the widths the columns are kept at: VECTOR_COS_W (register 1), VECTOR_REG9_W
// (register 9), VECTOR_OUT_W (pins 24-26); a bus bench keeps them at 32, 37, 32.
// read_vectors fills v_*[0:count-1]: v_cos cos λ and n, R, G, B as written; v_reg1 the COS
// code (register 1); v_out24..26 pins 24-26 (OUT_R/G/B); v_pass1/v_pass2 register 9 after
// each pass, sign-extended to 64 bits (REG9_PASS*_LO/HI; a device bench compares the low
// VECTOR_REG9_W); v_norm multiplier 39's s*K*A.
  real v_cos [0:MAX_VECTORS-1], v_norm [0:MAX_VECTORS-1];
  integer v_n [0:MAX_VECTORS-1], v_r [0:MAX_VECTORS-1], v_g [0:MAX_VECTORS-1], v_b [0:MAX_VECTORS-1];
  reg [VECTOR_COS_W-1:0] v_reg1 [0:MAX_VECTORS-1];
  reg [VECTOR_OUT_W-1:0] v_out24 [0:MAX_VECTORS-1], v_out25 [0:MAX_VECTORS-1],
                         v_out26 [0:MAX_VECTORS-1];
  reg [63:0] v_pass1 [0:MAX_VECTORS-1], v_pass2 [0:MAX_VECTORS-1];
  integer count;
  task read_vectors;
    integer fd, fields, n, r, g, b, pass;
    real cos, skip, norm;
    reg [63:0] h1, h2, h3, h4, h5, h6;
    reg [8*2048-1:0] header;
    begin
      fd = $fopen(VECTORS, "r");
      if (fd == 0) $fatal(1, "%0s: cannot read %0s", TB_NAME, VECTORS);
      fields = $fgets(header, fd);
      count = 0;
      fields = 25;
      while (!$feof(fd) && fields == 25) begin
        fields = $fscanf(fd, {"%f,%d,%d,%d,%d,%f,%f,%f,%f,%f,%f,%f,%f,%f,%f,%f,%f,%f,",
                              "0x%h,0x%h,0x%h,0x%h,0x%h,0x%h,%d\n"},
                         cos, n, r, g, b, skip, skip, skip, norm, skip, skip, skip, skip, skip,
                         skip, skip, skip, skip, h1, h2, h3, h4, h5, h6, pass);
        if (fields == 25) begin
          if (count == MAX_VECTORS) $fatal(1, "%0s: more than %0d vectors", TB_NAME, MAX_VECTORS);
          v_cos[count] = cos;
          v_n[count] = n; v_r[count] = r; v_g[count] = g; v_b[count] = b;
          v_norm[count] = norm;
          v_reg1[count] = h1[VECTOR_COS_W-1:0];
          // register 9 is signed (S14.22 by default): the HI word reads it sign-extended
          v_pass1[count] = $signed(h2[VECTOR_REG9_W-1:0]);
          v_pass2[count] = $signed(h3[VECTOR_REG9_W-1:0]);
          v_out24[count] = h4[VECTOR_OUT_W-1:0];
          v_out25[count] = h5[VECTOR_OUT_W-1:0];
          v_out26[count] = h6[VECTOR_OUT_W-1:0];
          count = count + 1;
        end else if (fields > 0) begin
          $fatal(1, "%0s: %0s line %0d: %0d of 25 fields", TB_NAME, VECTORS, count + 2, fields);
        end
      end
      $fclose(fd);
      if (count == 0) $fatal(1, "%0s: no vectors in %0s", TB_NAME, VECTORS);
    end
  endtask
