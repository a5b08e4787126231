// specular_device_parameters.vh: the parameters both device benches take
// (specular_device_tb.v, specular_device_sync_tb.v; rtl/tb/run_icarus.cmake and
// scripts/flows/gatelevel/gatesim.sh set them): specular_policy_parameters.vh's, the clock period, how
// often an operation is aborted by reset, and the timing tolerance at gate level.
// `include it first inside the bench module.
  `include "specular_policy_parameters.vh"  // VECTORS, ROM images, PINS_IMAGE, the policy
  parameter real T = 10.0;      // clock period (ns)
  parameter RESET_EVERY = 17;   // every RESET_EVERY-th operation follows one aborted by reset
  parameter MAX_VECTORS = 8192;
  // Gate level (scripts/flows/gatelevel/gatesim.sh, `define GATE_LEVEL): the edges the monitors time come
  // a cell delay after the clock's, so their time is checked to EDGE_TOLERANCE periods
  // (0: exactly).
  parameter real EDGE_TOLERANCE = 0.0;
