// Reads ROM 5 and ROM 38 of rtl/ through their ports and dumps what they give, for
// `specular_romgen --check` to compare with the C++ tables (test rtl_rom_contents).
// ROM 5: every mantissa word (a bus whose leading one is the top magnitude bit, the
// address just below it), then the leading-one detector and normaliser on every
// leading-one position, the zero-filled short mantissas, zero, negatives and random
// buses. ROM 38: every word of every bank. Widths and images are parameters (-P).
`default_nettype none
`timescale 1ns / 1ps

module rom_read_tb;
  parameter COS_FRAC = 16, N_BITS = 10;
  parameter ROM5_ADDR_BITS = 15, ROM5_WORD_BITS = 22;
  parameter REG9_INT = 14, REG9_FRAC = 22;
  parameter ROM38_INT = 9, ROM38_FRAC = 16, ROM38_BANK_BITS = 4;
  parameter ROM5_IMAGE = "rom5.hex", ROM38_IMAGE = "rom38.hex", DUMP = "rom_dump.txt";
  parameter RANDOM_BUSES = 4000;

  localparam LOG2_INT = $clog2((REG9_FRAC > REG9_INT ? REG9_FRAC : REG9_INT) + 1);
  localparam LOG2_W = 1 + LOG2_INT + ROM5_WORD_BITS;
  localparam BUS_W = 1 + REG9_INT + REG9_FRAC;
  localparam ROM38_W = ROM38_INT + ROM38_FRAC;

  reg  [BUS_W-1:0]           bus;
  wire [LOG2_W-1:0]          log2;
  reg  [ROM38_BANK_BITS-1:0] bank;
  reg  [N_BITS-1:0]          n;
  wire [ROM38_W-1:0]         k;

  rom5 #(.ADDR_BITS(ROM5_ADDR_BITS), .WORD_BITS(ROM5_WORD_BITS), .BUS_W(BUS_W),
         .BUS_FRAC(REG9_FRAC), .COS_FRAC(COS_FRAC), .LOG2_W(LOG2_W), .IMAGE(ROM5_IMAGE))
    rom5 (.bus(bus), .log2(log2));
  rom38 #(.N_BITS(N_BITS), .WORD_W(ROM38_W), .BANK_BITS(ROM38_BANK_BITS), .IMAGE(ROM38_IMAGE))
    rom38 (.bank(bank), .reg2(n), .k(k));

  integer fd, a, p, r;
  reg [BUS_W-1:0] one, word_address;
  reg [63:0] draw;

  task read_rom5(input [BUS_W-1:0] value);
    begin
      bus = value;
      #1 $fwrite(fd, "rom5 %h %h\n", bus, log2);
    end
  endtask

  initial begin
    if (BUS_W - 2 < ROM5_ADDR_BITS)
      $fatal(1, "rom_read_tb: a %0d-bit bus cannot address %0d mantissa bits below its top bit",
             BUS_W, ROM5_ADDR_BITS);
    fd = $fopen(DUMP, "w");
    if (fd == 0) $fatal(1, "rom_read_tb: cannot write %0s", DUMP);
    one = 1;
    // Every mantissa word: leading one at bit BUS_W-2, the address right below it.
    for (a = 0; a < (1 << ROM5_ADDR_BITS); a = a + 1) begin
      word_address = a;
      read_rom5((one << (BUS_W - 2)) | (word_address << (BUS_W - 2 - ROM5_ADDR_BITS)));
    end
    // The leading-one detector and normaliser at every position: a lone one, all ones
    // below it, and a one with the next bit set (short mantissas zero-filled).
    for (p = 0; p < BUS_W - 1; p = p + 1) begin
      read_rom5(one << p);
      read_rom5((one << (p + 1)) - one);
      if (p > 0) read_rom5((one << p) | (one << (p - 1)));
    end
    // Non-positive buses read log2 0: zero, -1, the most negative code, any negative.
    read_rom5({BUS_W{1'b0}});
    read_rom5({BUS_W{1'b1}});
    read_rom5({1'b1, {(BUS_W-1){1'b0}}});
    // Random buses with a random leading-one position.
    r = 1;
    for (a = 0; a < RANDOM_BUSES; a = a + 1) begin
      draw = {$random(r), $random(r)};
      p = {$random(r)} % BUS_W;
      read_rom5(draw[BUS_W-1:0] >> p);
    end
    // ROM 38: every word of every bank.
    for (a = 0; a < (1 << (ROM38_BANK_BITS + N_BITS)); a = a + 1) begin
      {bank, n} = a[ROM38_BANK_BITS+N_BITS-1:0];
      #1 $fwrite(fd, "rom38 %h %h %h\n", bank, n, k);
    end
    $fclose(fd);
    $display("rom_read_tb: dumped %0d ROM 5 and %0d ROM 38 reads to %0s",
             (1 << ROM5_ADDR_BITS) + 3 * (BUS_W - 1) - 1 + 3 + RANDOM_BUSES,
             1 << (ROM38_BANK_BITS + N_BITS), DUMP);
    $finish;
  end
endmodule

`default_nettype wire
