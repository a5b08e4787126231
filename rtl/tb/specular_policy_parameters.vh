// specular_policy_parameters.vh: the parameters scripts/flows/gatelevel/gatesim.sh and rtl/tb/run_icarus.cmake
// give every bench of a device top (specular_device_tb.v, specular_device_sync_tb.v,
// specular_ip_axi_gate_tb.v): the vectors, the ROM images, and the policy as the twin's
// wrapper ties it. `include it first inside the bench module.
  parameter VECTORS = "vectors.csv";
  parameter ROM5_IMAGE = "rom5.hex", ROM38_IMAGE = "rom38.hex";
  parameter PINS_IMAGE = "pins.hex";  // pins 19, 20 per constants policy (specular_romgen)
  parameter LITERAL = 0;        // 1: Saturation::literal
  parameter CONSTANTS = 0;      // Constants enum value: pins 19, 20 and ROM 38's bank
  parameter NORMALISATION = 0;  // Normalisation enum value: ROM 38's bank
