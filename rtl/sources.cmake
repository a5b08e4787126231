# The Verilog's folders, named once for rtl/, twin/ and ip/ (docs/rtl.md, "Layout"):
#   device/        the blocks of Fig. 1-2 by reference number and the two device tops
#   primitives/    gates, flip-flop, registers and the arithmetic the blocks share
#   design_space/  the design-space tops and their own blocks; variant_ports.vh, their
#                  common ports, is included from there (SPECULAR_RTL_INCLUDE_DIR)
# The scripts (silicon.sh, synth.sh, rtl_mutants.py) read the same three folders.
set(SPECULAR_RTL_DIR ${CMAKE_CURRENT_LIST_DIR})
set(specular_glob_depends CONFIGURE_DEPENDS)
if(CMAKE_SCRIPT_MODE_FILE)  # also read by cmake -P scripts (rtl/tb/read_from_clone.cmake)
  set(specular_glob_depends "")
endif()
file(GLOB SPECULAR_RTL_DEVICE_SOURCES ${specular_glob_depends}
     ${SPECULAR_RTL_DIR}/device/*.v ${SPECULAR_RTL_DIR}/primitives/*.v)
file(GLOB SPECULAR_RTL_DESIGN_SPACE_SOURCES ${specular_glob_depends} ${SPECULAR_RTL_DIR}/design_space/*.v)
set(SPECULAR_RTL_ALL_SOURCES ${SPECULAR_RTL_DEVICE_SOURCES} ${SPECULAR_RTL_DESIGN_SPACE_SOURCES})
# ip/: the whole IP, specular_ip_axi (docs/rtl_ip.md): the register block generated from the
# register map, the AXI4-Lite top, and the checker of its AXI4-Lite rules.
set(SPECULAR_RTL_IP_SOURCES ${SPECULAR_RTL_DIR}/ip/specular_reg_block.v ${SPECULAR_RTL_DIR}/ip/specular_ip_axi.v)
set(SPECULAR_RTL_IP_PROPS ${SPECULAR_RTL_DIR}/ip/specular_ip_axi_props.v)
# soc/: the integrator's example, specular_soc (docs/rtl_ip.md, "Placing the IP in an SoC"):
# an AXI4-Lite interconnect passing full addresses, a RAM, and the IP at a base of its own.
set(SPECULAR_RTL_SOC_SOURCES ${SPECULAR_RTL_DIR}/soc/axi_lite_interconnect.v
    ${SPECULAR_RTL_DIR}/soc/axi_lite_ram.v ${SPECULAR_RTL_DIR}/soc/specular_soc.v)
set(SPECULAR_RTL_INCLUDE_DIR ${SPECULAR_RTL_DIR}/design_space)
# The ROM images at the default widths, committed beside the Verilog that reads each with
# $readmemh: Yosys 0.23 looks for a $readmemh file in its working folder first, then in
# the folder of the file holding the $readmemh, so rtl/ reads from a clone run anywhere
# (a working folder with images of its own, a build's width set, still wins). pins.hex is
# the testbenches' (rtl/tb/). specular_romgen writes all five from the C++ tables; test
# rtl_rom_images_current fails when regenerating would change one (docs/rtl.md).
set(SPECULAR_RTL_ROM_IMAGES device/rom5.hex device/rom38.hex design_space/exp2.hex
    design_space/recip.hex tb/pins.hex)
