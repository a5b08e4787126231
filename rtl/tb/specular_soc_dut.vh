// The SoC benches' master and device under test (included inside the bench module):
// the parameter SEED (axi_lite_master.vh's stalls), the master (axi_lite_master.vh: the
// bench declares STALL first), the parameters IP_BASE, RAM_BASE, RAM_BYTES, ROM5_IMAGE,
// ROM38_IMAGE (run_soc.cmake sets them), specular_soc `dut` on them, and `soc_port`, the
// AXI4-Lite rules checked each edge on the SoC's port. The bench declares SOC_OPEN_WRITES
// and SOC_OPEN_READS first too: the requests its master keeps in flight (the checker's
// defaults, 2 and 1, for an in-order master; 4 and 4, the interconnect's, for one that
// keeps more).
  parameter SEED = 1;
  `include "axi_lite_master.vh"
  parameter ROM5_IMAGE = "rom5.hex", ROM38_IMAGE = "rom38.hex";
  parameter [31:0] IP_BASE = 32'h4000_0000;
  parameter [31:0] RAM_BASE = 32'h0000_0000;
  parameter RAM_BYTES = 65536;
  wire done_irq;

  specular_soc #(.IP_BASE(IP_BASE), .RAM_BASE(RAM_BASE), .RAM_BYTES(RAM_BYTES),
                 .ROM5_IMAGE(ROM5_IMAGE), .ROM38_IMAGE(ROM38_IMAGE)) dut (
    `include "axi_lite_slave_ports.vh"
  );

  specular_ip_axi_props #(.MAX_OPEN_WRITES(SOC_OPEN_WRITES), .MAX_OPEN_READS(SOC_OPEN_READS)) soc_port (
    `include "axi_lite_check_ports.vh"
  );
