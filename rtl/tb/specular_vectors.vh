// specular_vectors.vh: the operations of `specular_tb --format csv` (Core's bits) for the
// bus testbenches (specular_ip_axi_tb.v, specular_soc_responses_tb.v). `include it inside
// the testbench module, after its parameters VECTORS (the CSV file) and MAX_VECTORS.
// read_vectors fills v_*[0:count-1]: n, R, G, B as written; v_reg1 the COS code (register
// 1); v_out24..26 pins 24-26 (OUT_R/G/B); v_pass1/v_pass2 register 9 after each pass,
// sign-extended to 64 bits (REG9_PASS*_LO/HI); v_norm multiplier 39's s*K*A.
  integer v_n [0:MAX_VECTORS-1], v_r [0:MAX_VECTORS-1], v_g [0:MAX_VECTORS-1], v_b [0:MAX_VECTORS-1];
  reg [31:0] v_reg1 [0:MAX_VECTORS-1], v_out24 [0:MAX_VECTORS-1], v_out25 [0:MAX_VECTORS-1],
             v_out26 [0:MAX_VECTORS-1];
  reg [63:0] v_pass1 [0:MAX_VECTORS-1], v_pass2 [0:MAX_VECTORS-1];
  real v_norm [0:MAX_VECTORS-1];
  integer count;
  task read_vectors;
    integer fd, fields, n, r, g, b, pass;
    real cos, skip, norm;
    reg [63:0] h1, h2, h3, h4, h5, h6;
    reg [8*2048-1:0] header;
    begin
      fd = $fopen(VECTORS, "r");
      if (fd == 0) $fatal(1, "read_vectors: cannot read %0s", VECTORS);
      fields = $fgets(header, fd);
      count = 0;
      fields = 25;
      while (!$feof(fd) && fields == 25) begin
        fields = $fscanf(fd, {"%f,%d,%d,%d,%d,%f,%f,%f,%f,%f,%f,%f,%f,%f,%f,%f,%f,%f,",
                              "0x%h,0x%h,0x%h,0x%h,0x%h,0x%h,%d\n"},
                         cos, n, r, g, b, skip, skip, skip, norm, skip, skip, skip, skip, skip,
                         skip, skip, skip, skip, h1, h2, h3, h4, h5, h6, pass);
        if (fields == 25) begin
          if (count == MAX_VECTORS) $fatal(1, "read_vectors: more than %0d vectors", MAX_VECTORS);
          v_n[count] = n; v_r[count] = r; v_g[count] = g; v_b[count] = b;
          v_norm[count] = norm;
          v_reg1[count] = h1[31:0];
          // register 9 is S14.22, 37 bits: the HI word reads it sign-extended
          v_pass1[count] = {{27{h2[36]}}, h2[36:0]};
          v_pass2[count] = {{27{h3[36]}}, h3[36:0]};
          v_out24[count] = h4[31:0]; v_out25[count] = h5[31:0]; v_out26[count] = h6[31:0];
          count = count + 1;
        end else if (fields > 0) begin
          $fatal(1, "read_vectors: %0s line %0d: %0d of 25 fields", VECTORS, count + 2, fields);
        end
      end
      $fclose(fd);
      if (count == 0) $fatal(1, "read_vectors: no vectors in %0s", VECTORS);
    end
  endtask
