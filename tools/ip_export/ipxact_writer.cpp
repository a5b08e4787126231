#include "ipxact_writer.h"
#include "register_roles.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>

#include "specular/tlm/register_fields.h"
#include "specular/tlm/register_map.h"

namespace specular {
namespace ip_export {
namespace {

std::string escape(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

/// A SystemVerilog-style literal, as IP-XACT 2014's expressions take: 'h0005_9965.
std::string hex_literal(std::uint32_t value) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "'h%08X", value);
  return buffer;
}

const char* const vendor = "specular-unit";
const char* const bus_library = "interface";
const char* const bus_name = "tlm2_generic_payload";
const char* const abstraction_name = "tlm2_generic_payload_tlm";
const char* const bus_version = "1.0";

std::string vlnv_attributes(const char* name) {
  return std::string("vendor=\"") + vendor + "\" library=\"" + bus_library + "\" name=\"" + name +
         "\" version=\"" + bus_version + "\"";
}

/// An indenting writer of the few element shapes the component has.
class Xml {
 public:
  void open(const std::string& tag, const std::string& attributes = "") {
    line("<ipxact:" + tag + (attributes.empty() ? "" : " " + attributes) + ">");
    ++depth_;
  }
  void close(const std::string& tag) {
    --depth_;
    line("</ipxact:" + tag + ">");
  }
  void leaf(const std::string& tag, const std::string& text, const std::string& attributes = "") {
    line("<ipxact:" + tag + (attributes.empty() ? "" : " " + attributes) + ">" + escape(text) +
         "</ipxact:" + tag + ">");
  }
  void empty(const std::string& tag, const std::string& attributes) {
    line("<ipxact:" + tag + " " + attributes + "/>");
  }
  void line(const std::string& text) { out_ << std::string(2 * depth_, ' ') << text << "\n"; }
  std::string str() const { return out_.str(); }

 private:
  std::ostringstream out_;
  int depth_ = 0;
};

/// IP-XACT's words for a field's access: access, modifiedWriteValue (or "").
struct FieldAccessWords {
  const char* access;
  const char* modified_write_value;
};

FieldAccessWords access_words(Access access) {
  switch (access) {
    case Access::read_only: return {"read-only", ""};
    case Access::read_write: return {"read-write", ""};
    case Access::write_1_to_clear: return {"read-write", "oneToClear"};
    // A write of 1 acts and the field reads 0: write-only, as the RDL's `sw = w;
    // singlepulse` and the tables' W (modifiedWriteValue=modify made PeakRDL-ipxact's
    // importer refuse the file: "onwrite = wuser" on a field that is not external).
    case Access::self_clearing: return {"write-only", ""};
  }
  return {"read-only", ""};
}

/// The register's own access: read-only if every field is, else read-write.
const char* register_access(Reg reg) {
  for (const FieldInfo& f : fields_of(reg))
    if (f.access != Access::read_only) return "read-write";
  return "read-only";
}

/// `with_reset` false: a memory window's word (BATCH_COS, BATCH_OUT), which no reset
/// touches: a register model then holds no per-word reset check for its 4 096 words.
/// `parameter` not empty: the register reads that component parameter (specular_ip_axi's
/// CONFIG_VALUE, PIN19_H_VALUE, PIN20_A_VALUE), so the field's reset is an IP-XACT 2014
/// expression of it (SystemVerilog operators on the parameter's id), not a number that
/// goes stale when an integrator sets the parameter.
std::string reset_expression(const FieldInfo& f, const std::string& parameter) {
  if (f.shift == 0 && f.width == 32) return parameter;
  const std::string shifted = f.shift == 0 ? parameter : "(" + parameter + " >> " + std::to_string(f.shift) + ")";
  char mask[16];
  std::snprintf(mask, sizeof mask, "'h%X", static_cast<unsigned>((std::uint64_t{1} << f.width) - 1));
  return shifted + " & " + mask;
}

void write_field(Xml& x, const FieldInfo& f, std::uint32_t register_reset, bool with_reset = true,
                 const std::string& parameter = "") {
  x.open("field");
  x.leaf("name", f.name);
  x.leaf("description", f.description);
  x.leaf("bitOffset", std::to_string(f.shift));
  if (with_reset) {
    x.open("resets");
    x.open("reset");
    x.leaf("value", parameter.empty() ? hex_literal((register_reset & f.mask()) >> f.shift)
                                      : reset_expression(f, parameter));
    x.close("reset");
    x.close("resets");
  }
  x.leaf("bitWidth", std::to_string(f.width));
  if (is_volatile(f.reg))  // the device changes it (register_roles.h)
    x.leaf("volatile", "true");
  const FieldAccessWords words = access_words(f.access);
  x.leaf("access", words.access);
  if (f.values != FieldValues::none) {
    x.open("enumeratedValues");
    for (const FieldValue& v : field_values(f.values)) {
      x.open("enumeratedValue");
      x.leaf("name", v.name);
      if (!v.description.empty()) x.leaf("description", v.description);
      x.leaf("value", std::to_string(v.value));
      x.close("enumeratedValue");
    }
    x.close("enumeratedValues");
  }
  if (*words.modified_write_value) x.leaf("modifiedWriteValue", words.modified_write_value);
  x.close("field");
}

/// A single register `reg` at `offset` (its own, or its word in an alias window).
void write_register(Xml& x, Reg reg, std::uint32_t offset, std::uint32_t reset,
                    const std::string& description, const std::string& parameter = "") {
  const RegisterInfo& row = info(reg);
  x.open("register");
  x.leaf("name", row.name);
  x.leaf("description", description);
  x.leaf("addressOffset", hex_literal(offset));
  x.leaf("size", "32");
  x.leaf("access", register_access(reg));
  for (const FieldInfo& f : fields_of(reg)) write_field(x, f, reset, true, parameter);
  x.close("register");
}

bool is_alias_window(const RegisterInfo& row) {
  return row.reg == Reg::operands || row.reg == Reg::results;
}

/// The parameter of specular_ip_axi a register reads (specular_reg_block.v), or "".
std::string configuring_parameter(Reg reg) {
  switch (reg) {
    case Reg::config: return "CONFIG_VALUE";
    case Reg::pin19_h: return "PIN19_H_VALUE";
    case Reg::pin20_a: return "PIN20_A_VALUE";
    default: return "";
  }
}

/// `windows` false: the map of specular_ip_axi, which has no batch windows (holes there,
/// BATCH_CAPACITY 0: docs/decisions.md).
void write_memory_map(Xml& x, bool windows, const ComponentFacts& facts) {
  // resolved: the values the top was read with, in place of expressions of them
  const auto value_of = [&facts](const std::string& name) {
    for (const VerilogParameter& p : facts.tops.front().parameters)
      if (p.name == name) return p.value;
    throw std::invalid_argument("write_memory_map: no parameter " + name);
  };
  x.open("memoryMaps");
  x.open("memoryMap");
  x.leaf("name", "registers");
  x.leaf("description", windows ? "The TLM-2.0 target's registers and windows (docs/tlm.md)"
                                : "specular_ip_axi's registers (docs/rtl_ip.md): the TLM-2.0 "
                                  "target's without the batch windows, whose offsets are holes");
  x.open("addressBlock");
  x.leaf("name", "specular");
  x.leaf("description",
         windows ? "Every register and window; bytes outside them are holes (TLM_ADDRESS_ERROR_RESPONSE)"
                 : "Every register; the IP decodes the low ADDR_WIDTH bits of the address (2 ** "
                   "ADDR_WIDTH bytes, 0x8000 at the default 15): bytes no register covers, up to "
                   "there, answer DECERR");
  x.leaf("baseAddress", hex_literal(0));
  // specular_ip_axi answers (DECERR above the registers) in the whole window its address
  // width decodes: an expression of the component parameter ADDR_WIDTH
  if (windows) {
    x.leaf("range", hex_literal(map_size));
  } else if (facts.resolved) {
    char range[24];
    std::snprintf(range, sizeof range, "'h%llX",
                  static_cast<unsigned long long>(std::uint64_t{1} << value_of("ADDR_WIDTH")));
    x.leaf("range", range);
  } else {
    x.leaf("range", "2 ** ADDR_WIDTH");
  }
  x.leaf("width", "32");
  x.leaf("usage", "register");
  for (const RegisterInfo& row : register_map) {
    const bool batch_window = row.reg == Reg::batch_cos || row.reg == Reg::batch_out;
    if (batch_window && !windows) continue;
    if (row.reg == Reg::batch_capacity && !windows) {
      write_register(x, row.reg, row.offset, 0,
                     row.description + std::string(" (0 on this IP: no batch windows, their "
                                                   "offsets answer DECERR; the TLM-2.0 targets "
                                                   "read ") + std::to_string(batch_capacity) + ")");
    } else if (row.words == 1 && !windows && !configuring_parameter(row.reg).empty()) {
      const std::string parameter = configuring_parameter(row.reg);
      if (facts.resolved)
        write_register(x, row.reg, row.offset, static_cast<std::uint32_t>(value_of(parameter)),
                       row.description + std::string(" (on this IP: parameter ") + parameter +
                           ", resolved to " + hex_literal(static_cast<std::uint32_t>(value_of(parameter))) + ")");
      else
        write_register(x, row.reg, row.offset, row.reset,
                       row.description + std::string(" (on this IP: parameter ") + parameter + ")",
                       parameter);
    } else if (row.reg == Reg::batch_capacity) {
      write_register(x, row.reg, row.offset, row.reset,
                     row.description + std::string(" (") + std::to_string(batch_capacity) +
                         " on the TLM-2.0 targets, their default, with the windows below; "
                         "specular_ip_axi reads 0: specular_ip_axi.xml)");
    } else if (row.words == 1) {
      write_register(x, row.reg, row.offset, row.reset, row.description);
    } else if (is_alias_window(row)) {
      // A register file of the registers it aliases, each with its own fields and reset.
      x.open("registerFile");
      x.leaf("name", row.name);
      x.leaf("description", row.description);
      x.leaf("addressOffset", hex_literal(row.offset));
      x.leaf("range", hex_literal(4 * row.words));
      for (std::uint32_t w = 0; w < row.words; ++w) {
        const Reg alias = row.reg == Reg::operands ? operand_register(w) : result_register(w);
        write_register(x, alias, 4 * w, reset_of_word(row, w),
                       std::string("Alias of ") + info(alias).name + " (" +
                           hex_literal(info(alias).offset) + "): " + info(alias).description);
      }
      x.close("registerFile");
    } else {
      // A window of like words: a register array.
      x.open("register");
      x.leaf("name", row.name);
      x.leaf("description", row.description);
      x.leaf("dim", std::to_string(row.words));
      x.leaf("addressOffset", hex_literal(row.offset));
      x.leaf("size", "32");
      x.leaf("access", register_access(row.reg));
      for (const FieldInfo& f : fields_of(row.reg)) write_field(x, f, row.reset, false);
      x.close("register");
    }
  }
  x.close("addressBlock");
  x.leaf("addressUnitBits", "8");
  x.close("memoryMap");
  x.close("memoryMaps");
}

// ---- the model: views, instantiations, ports ----------------------------------------

struct SystemCView {
  const char* view;
  const char* module;
  const char* description;
};
const SystemCView systemc_views[] = {
    {"tlm_lt", "specular::SpecularLtTarget",
     "Loosely timed: the bit-accurate core with annotated latency (specular/tlm/lt_target.h)"},
    {"tlm_pin", "specular::SpecularPinTarget",
     "The pin-level SystemC netlist behind a transactor (specular/tlm/pin_target.h)"},
    {"tlm_rtl", "specular::SpecularRtlTarget",
     "The verilated specular_device behind a transactor (specular/twin/rtl_target.h, "
     "find_package COMPONENTS rtl)"},
    {"tlm_rtl_sync", "specular::SpecularRtlSyncTarget",
     "The verilated specular_device_sync behind a transactor (specular/twin/rtl_sync_target.h, "
     "find_package COMPONENTS rtl)"},
};

std::string view_of_top(const VerilogModule& top) {
  return top.name == "specular_device" ? "rtl" : top.name == "specular_device_sync" ? "rtl_sync"
         : top.name == "specular_ip_axi" ? "rtl_axi" : top.name;
}
std::string prefix_of_top(const VerilogModule& top) {
  return top.name == "specular_device" ? "device" : top.name == "specular_device_sync" ? "sync"
         : top.name == "specular_ip_axi" ? "axi" : top.name;
}

void write_views(Xml& x, const ComponentFacts& facts) {
  x.open("views");
  for (const SystemCView& v : systemc_views) {
    if (!facts.systemc) break;
    x.open("view");
    x.leaf("name", v.view);
    x.leaf("description", v.description);
    x.leaf("envIdentifier", "systemc:*:*");
    x.leaf("componentInstantiationRef", v.view);
    x.close("view");
  }
  for (const VerilogModule& top : facts.tops) {
    x.open("view");
    x.leaf("name", view_of_top(top));
    x.leaf("description", "The Verilog top " + top.name + " (" + top.file + ")");
    x.leaf("envIdentifier", "verilog:*:*");
    x.leaf("componentInstantiationRef", view_of_top(top));
    x.close("view");
  }
  x.close("views");
}

std::string parameter_value(const VerilogParameter& p) {
  return p.is_string ? "\"" + p.text + "\"" : std::to_string(p.value);
}

/// The allowed range of a parameter the Verilog refuses outside it (specular_ip_axi.v's
/// ADDR_WIDTH_OUT_OF_RANGE), as IP-XACT's minimum and maximum.
std::string parameter_bounds(const VerilogModule& top, const VerilogParameter& p) {
  std::int64_t minimum = 0, maximum = 0;
  if (!parameter_range(top.name, p.name, minimum, maximum)) return "";
  return " minimum=\"" + std::to_string(minimum) + "\" maximum=\"" + std::to_string(maximum) + "\"";
}

/// specular_ip_axi's parameters as the component's, ids their names, so that expressions
/// (the ports' widths, the resets of CONFIG, PIN19_H and PIN20_A, the address block's
/// range) name them and an integrator sets each in one place.
void write_component_parameters(Xml& x, const ComponentFacts& facts) {
  const VerilogModule& top = facts.tops.front();
  if (top.name != "specular_ip_axi") return;
  x.open("parameters");
  for (const VerilogParameter& p : top.parameters) {
    x.open("parameter", "parameterId=\"" + p.name + "\"" + parameter_bounds(top, p) +
                            " resolve=\"user\" type=\"" + (p.is_string ? "string" : "longint") + "\"");
    x.leaf("name", p.name);
    if (p.width > 0) {
      x.open("vectors");
      x.open("vector");
      x.leaf("left", std::to_string(p.width - 1));
      x.leaf("right", "0");
      x.close("vector");
      x.close("vectors");
    }
    x.leaf("value", parameter_value(p));
    x.close("parameter");
  }
  x.close("parameters");
}

void write_instantiations(Xml& x, const ComponentFacts& facts) {
  x.open("instantiations");
  for (const SystemCView& v : systemc_views) {
    if (!facts.systemc) break;
    x.open("componentInstantiation");
    x.leaf("name", v.view);
    x.leaf("language", "systemc");
    x.leaf("moduleName", v.module);
    x.open("fileSetRef");
    x.leaf("localName", "systemc_headers");
    x.close("fileSetRef");
    x.open("fileSetRef");
    x.leaf("localName", "systemc_libraries");
    x.close("fileSetRef");
    x.close("componentInstantiation");
  }
  for (std::size_t t = 0; t < facts.tops.size(); ++t) {
    const VerilogModule& top = facts.tops[t];
    x.open("componentInstantiation");
    x.leaf("name", view_of_top(top));
    x.leaf("language", "verilog");
    x.leaf("moduleName", top.name);
    x.open("moduleParameters");
    // specular_ip_axi's module parameters follow the component's parameters of the same
    // name (write_component_parameters), which its memory map and ports refer to too
    const bool follows = top.name == "specular_ip_axi" && !facts.resolved;
    for (const VerilogParameter& p : top.parameters) {
      x.open("moduleParameter", "parameterId=\"" + prefix_of_top(top) + "_" + p.name + "\"" +
                                    (follows ? "" : " resolve=\"user\"") + " type=\"" +
                                    (p.is_string ? "string" : "longint") + "\"");
      x.leaf("name", p.name);
      if (p.width > 0) {
        x.open("vectors");
        x.open("vector");
        x.leaf("left", std::to_string(p.width - 1));
        x.leaf("right", "0");
        x.close("vector");
        x.close("vectors");
      }
      x.leaf("value", follows ? p.name : parameter_value(p));
      x.close("moduleParameter");
    }
    x.close("moduleParameters");
    x.open("fileSetRef");
    x.leaf("localName", "verilog_" + view_of_top(top));
    x.close("fileSetRef");
    x.open("fileSetRef");
    x.leaf("localName", "rom_images");
    x.close("fileSetRef");
    x.close("componentInstantiation");
  }
  x.close("instantiations");
}

/// `expressions`: the component has its top's parameters (specular_ip_axi), so a width
/// that follows one is an expression of it; elsewhere the width at the defaults.
void write_wire_port(Xml& x, const VerilogPort& p, const std::vector<std::string>& views,
                     bool expressions) {
  x.open("port");
  x.leaf("name", p.name);
  x.open("wire");
  x.leaf("direction", p.direction);
  if (p.is_vector) {
    x.open("vectors");
    x.open("vector");
    x.leaf("left", expressions && !p.msb_expression.empty() ? p.msb_expression  // ADDR_WIDTH - 1
                                                             : std::to_string(p.msb));
    x.leaf("right", std::to_string(p.lsb));
    x.close("vector");
    x.close("vectors");
  }
  x.open("wireTypeDefs");
  x.open("wireTypeDef");
  x.leaf("typeName", p.is_signed ? "wire signed" : "wire");
  for (const std::string& v : views) x.leaf("viewRef", v);
  x.close("wireTypeDef");
  x.close("wireTypeDefs");
  x.close("wire");
  x.close("port");
}

void write_ports(Xml& x, const ComponentFacts& facts) {
  x.open("ports");
  if (facts.systemc) {
    // The SystemC targets' socket and interrupt.
    x.open("port");
    x.leaf("name", "socket");
    x.leaf("description",
           "tlm_utils::simple_target_socket<T, 32>: the registers of memory map 'registers'");
    x.open("transactional");
    x.leaf("initiative", "provides");
    x.leaf("busWidth", "32");
    x.open("transTypeDefs");
    x.open("transTypeDef");
    x.leaf("typeName", "tlm_utils::simple_target_socket");
    for (const SystemCView& v : systemc_views) x.leaf("viewRef", v.view);
    x.close("transTypeDef");
    x.close("transTypeDefs");
    x.close("transactional");
    x.close("port");
    x.open("port");
    x.leaf("name", "done_irq");
    x.leaf("description", "Level: high while STATUS.DONE is set (sc_core::sc_out<bool>; may stay unbound)");
    x.open("wire");
    x.leaf("direction", "out");
    x.open("wireTypeDefs");
    x.open("wireTypeDef");
    x.leaf("typeName", "sc_core::sc_out<bool>");
    for (const SystemCView& v : systemc_views) x.leaf("viewRef", v.view);
    x.close("wireTypeDef");
    x.close("wireTypeDefs");
    x.close("wire");
    x.close("port");
  }
  // The Verilog top's ports, every one present (one top per component).
  const VerilogModule& top = facts.tops.front();
  for (const VerilogPort& p : top.ports)
    write_wire_port(x, p, {view_of_top(top)}, top.name == "specular_ip_axi" && !facts.resolved);
  x.close("ports");
}

void write_file_sets(Xml& x, const ComponentFacts& facts) {
  const std::string prefix = "../../../";  // from <prefix>/share/SpecularUnit/ip/
  x.open("fileSets");
  if (facts.systemc) {
  x.open("fileSet");
  x.leaf("name", "systemc_headers");
  x.leaf("description",
         "The headers a SystemC platform includes, in the installed package (paths from "
         "share/SpecularUnit/ip/); the folder holds the headers they include");
  for (const char* header : {"specular/tlm/lt_target.h", "specular/tlm/pin_target.h",
                             "specular/tlm/target.h", "specular/tlm/register_map.h",
                             "specular/tlm/register_fields.h", "specular/twin/rtl_target.h",
                             "specular/twin/rtl_sync_target.h", "specular/core.h"}) {
    x.open("file");
    x.leaf("name", prefix + "include/" + header);
    x.leaf("fileType", "systemCSource");
    x.leaf("isIncludeFile", "true");
    x.close("file");
  }
  x.leaf("dependency", prefix + "include");
  x.close("fileSet");
  x.open("fileSet");
  x.leaf("name", "systemc_libraries");
  x.leaf("description",
         "The installed libraries (find_package(SpecularUnit) links them): core without "
         "SystemC, the SystemC model and TLM targets, and (COMPONENTS rtl) the twin");
  for (const char* lib : {"libspecular_core.a", "libspecular.a", "libspecular_twin.a",
                          "libspecular_rtl_models.a"}) {
    x.open("file");
    x.leaf("name", prefix + facts.libdir + "/" + lib);
    x.leaf("fileType", "swObjectLibrary");
    x.close("file");
  }
  x.open("file");
  x.leaf("name", prefix + facts.libdir + "/cmake/SpecularUnit/SpecularUnitConfig.cmake");
  x.leaf("fileType", "user", "user=\"cmakePackageConfig\"");
  x.leaf("description", "find_package(SpecularUnit CONFIG REQUIRED)");
  x.close("file");
  x.close("fileSet");
  }
  for (std::size_t t = 0; t < facts.tops.size(); ++t) {
    x.open("fileSet");
    x.leaf("name", "verilog_" + view_of_top(facts.tops[t]));
    x.leaf("description",
           facts.tops[t].name +
               " and the modules it instantiates (installed in share/SpecularUnit/rtl/, as in "
               "the source tree's rtl/); ROM images from specular_romgen (docs/rtl.md)");
    for (const std::string& file : facts.top_files[t]) {
      x.open("file");
      x.leaf("name", "../rtl/" + file);
      x.leaf("fileType", "verilogSource-2001");
      x.close("file");
    }
    x.close("fileSet");
  }
  // ROM 5's and ROM 38's contents, which rom5.v and rom38.v read with $readmemh from the
  // files their IMAGE parameters name (the tops' ROM5_IMAGE, ROM38_IMAGE). Committed and
  // installed beside those two files (rtl/device/), where Yosys looks after its working
  // folder: the paths hold in the source tree and in the install alike.
  x.open("fileSet");
  x.leaf("name", "rom_images");
  x.leaf("description",
         "The ROM images the Verilog tops read with $readmemh (parameters ROM5_IMAGE, "
         "ROM38_IMAGE), at the default widths, written by specular_romgen from the C++ "
         "tables; beside rom5.v and rom38.v in the source tree's rtl/device/ and in "
         "share/SpecularUnit/rtl/device/");
  for (const char* image : {"rom5.hex", "rom38.hex"}) {
    x.open("file");
    x.leaf("name", std::string("../rtl/device/") + image);
    x.leaf("fileType", "user", "user=\"verilogReadmemhImage\"");
    x.close("file");
  }
  x.close("fileSet");
  x.close("fileSets");
}

/// The Verilog view of the whole IP (rtl/ip/specular_ip_axi.v): ARM's AMBA AXI4-Lite bus
/// definition and RTL abstraction, its signals mapped to the top's ports, the same
/// memory map (the batch windows are holes there: docs/decisions.md).
void write_axi_interface(Xml& x, const ComponentFacts& facts) {
  const VerilogModule* axi = nullptr;
  for (const VerilogModule& top : facts.tops)
    if (top.name == "specular_ip_axi") axi = &top;
  if (axi == nullptr) return;
  x.open("busInterface");
  x.leaf("name", "s_axi");
  x.leaf("description",
         "AMBA AXI4-Lite slave of specular_ip_axi: 32-bit data, byte strobes, the register "
         "map 'registers' without the batch windows (docs/rtl_ip.md). AWADDR and ARADDR are "
         "ADDR_WIDTH bits (parameter, 15 to 32, default 15): the offset in the IP's window of "
         "2 ** ADDR_WIDTH bytes; connect the low bits of the interconnect's address, which "
         "selects the IP by the bits above (any base aligned to 2 ** ADDR_WIDTH)");
  x.empty("busType", "vendor=\"amba.com\" library=\"AMBA4\" name=\"AXI4-Lite\" version=\"r0p0_0\"");
  x.open("abstractionTypes");
  x.open("abstractionType");
  x.leaf("viewRef", view_of_top(*axi));
  x.empty("abstractionRef",
          "vendor=\"amba.com\" library=\"AMBA4\" name=\"AXI4-Lite_rtl\" version=\"r0p0_0\"");
  x.open("portMaps");
  const std::pair<const char*, const char*> signals[] = {
      {"ACLK", "aclk"},         {"ARESETn", "aresetn"},
      {"AWVALID", "s_axi_awvalid"}, {"AWREADY", "s_axi_awready"}, {"AWADDR", "s_axi_awaddr"},
      {"AWPROT", "s_axi_awprot"},   {"WVALID", "s_axi_wvalid"},   {"WREADY", "s_axi_wready"},
      {"WDATA", "s_axi_wdata"},     {"WSTRB", "s_axi_wstrb"},     {"BVALID", "s_axi_bvalid"},
      {"BREADY", "s_axi_bready"},   {"BRESP", "s_axi_bresp"},     {"ARVALID", "s_axi_arvalid"},
      {"ARREADY", "s_axi_arready"}, {"ARADDR", "s_axi_araddr"},   {"ARPROT", "s_axi_arprot"},
      {"RVALID", "s_axi_rvalid"},   {"RREADY", "s_axi_rready"},   {"RDATA", "s_axi_rdata"},
      {"RRESP", "s_axi_rresp"}};
  for (const auto& [logical, physical] : signals) {
    x.open("portMap");
    x.open("logicalPort");
    x.leaf("name", logical);
    x.close("logicalPort");
    x.open("physicalPort");
    x.leaf("name", physical);
    x.close("physicalPort");
    x.close("portMap");
  }
  x.close("portMaps");
  x.close("abstractionType");
  x.close("abstractionTypes");
  x.open("slave");
  x.empty("memoryMapRef", "memoryMapRef=\"registers\"");
  x.close("slave");
  x.leaf("bitsInLau", "8");
  x.close("busInterface");
}

/// done_irq as an interrupt interface: Xilinx's interrupt bus type (the one IP-XACT
/// interrupt definition integration tools ship; IEEE and Accellera define none), the
/// component its master (it drives the line), SENSITIVITY LEVEL_HIGH: high while
/// STATUS.DONE is set. docs/ipxact.md says why this VLNV.
void write_interrupt_interface(Xml& x, const std::vector<std::string>& views) {
  x.open("busInterface");
  x.leaf("name", "done_irq");
  x.leaf("description",
         "Interrupt: level, active high, high while STATUS.DONE is set; cleared by writing 1 "
         "to STATUS.DONE (docs/tlm.md)");
  x.empty("busType", "vendor=\"xilinx.com\" library=\"signal\" name=\"interrupt\" version=\"1.0\"");
  x.open("abstractionTypes");
  x.open("abstractionType");
  for (const std::string& v : views) x.leaf("viewRef", v);
  x.empty("abstractionRef",
          "vendor=\"xilinx.com\" library=\"signal\" name=\"interrupt_rtl\" version=\"1.0\"");
  x.open("portMaps");
  x.open("portMap");
  x.open("logicalPort");
  x.leaf("name", "INTERRUPT");
  x.close("logicalPort");
  x.open("physicalPort");
  x.leaf("name", "done_irq");
  x.close("physicalPort");
  x.close("portMap");
  x.close("portMaps");
  x.close("abstractionType");
  x.close("abstractionTypes");
  x.line("<ipxact:master/>");
  x.open("parameters");
  x.open("parameter", "parameterId=\"done_irq_SENSITIVITY\" type=\"string\"");
  x.leaf("name", "SENSITIVITY");
  x.leaf("value", "\"LEVEL_HIGH\"");
  x.close("parameter");
  x.close("parameters");
  x.close("busInterface");
}

}  // namespace

bool parameter_range(const std::string& top, const std::string& name, std::int64_t& minimum,
                     std::int64_t& maximum) {
  // specular_ip_axi.v's generate block ADDR_WIDTH_OUT_OF_RANGE
  if (top == "specular_ip_axi" && name == "ADDR_WIDTH") {
    minimum = 15;
    maximum = 32;
    return true;
  }
  return false;
}

std::string ipxact_component(const ComponentFacts& facts) {
  if (facts.tops.size() != 1 || facts.top_files.size() != 1)
    throw std::invalid_argument("ipxact_component: " + facts.name + " has " +
                                std::to_string(facts.tops.size()) + " Verilog tops, one expected");
  const bool axi = facts.tops.front().name == "specular_ip_axi";
  Xml x;
  x.line("<?xml version=\"1.0\" encoding=\"UTF-8\"?>");
  x.line("<!-- Generated by specular_ip_export from modules/include/specular/tlm/register_map.h,");
  x.line("     register_fields.h and the Verilog tops' headers; edit those, not this file (docs/ipxact.md). -->");
  x.open("component",
         "xmlns:ipxact=\"http://www.accellera.org/XMLSchema/IPXACT/1685-2014\" "
         "xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
         "xsi:schemaLocation=\"http://www.accellera.org/XMLSchema/IPXACT/1685-2014 "
         "http://www.accellera.org/XMLSchema/IPXACT/1685-2014/index.xsd\"");
  x.leaf("vendor", "specular-unit");
  x.leaf("library", "ip");
  x.leaf("name", facts.name);
  x.leaf("version", facts.version);
  if (facts.systemc || axi) x.open("busInterfaces");
  if (facts.systemc) {
  x.open("busInterface");
  x.leaf("name", "socket");
  x.leaf("description",
         "The TLM-2.0 target socket: 32-bit generic payload, register map 'registers' "
         "(docs/tlm.md); the bus type names TLM-2.0's generic payload (docs/ipxact.md)");
  x.empty("busType", vlnv_attributes(bus_name));
  x.open("abstractionTypes");
  x.open("abstractionType");
  for (const SystemCView& v : systemc_views) x.leaf("viewRef", v.view);
  x.empty("abstractionRef", vlnv_attributes(abstraction_name));
  x.open("portMaps");
  x.open("portMap");
  x.open("logicalPort");
  x.leaf("name", "generic_payload");
  x.close("logicalPort");
  x.open("physicalPort");
  x.leaf("name", "socket");
  x.close("physicalPort");
  x.close("portMap");
  x.close("portMaps");
  x.close("abstractionType");
  x.close("abstractionTypes");
  x.open("slave");
  x.empty("memoryMapRef", "memoryMapRef=\"registers\"");
  x.close("slave");
  x.leaf("bitsInLau", "8");
  x.close("busInterface");
  }
  write_axi_interface(x, facts);
  if (facts.systemc) {
    std::vector<std::string> views;
    for (const SystemCView& v : systemc_views) views.push_back(v.view);
    write_interrupt_interface(x, views);
  } else if (axi) {
    write_interrupt_interface(x, {view_of_top(facts.tops.front())});
  }
  if (facts.systemc || axi) x.close("busInterfaces");
  if (facts.systemc || axi) write_memory_map(x, !axi, facts);
  x.open("model");
  write_views(x, facts);
  write_instantiations(x, facts);
  write_ports(x, facts);
  x.close("model");
  write_file_sets(x, facts);
  x.leaf("description", facts.description);
  write_component_parameters(x, facts);
  x.close("component");
  return x.str();
}

namespace {
void document_start(Xml& x, const std::string& root) {
  x.line("<?xml version=\"1.0\" encoding=\"UTF-8\"?>");
  x.line("<!-- Generated by specular_ip_export; the bus type of specular_unit.xml's socket (docs/ipxact.md). -->");
  x.open(root,
         "xmlns:ipxact=\"http://www.accellera.org/XMLSchema/IPXACT/1685-2014\" "
         "xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\" "
         "xsi:schemaLocation=\"http://www.accellera.org/XMLSchema/IPXACT/1685-2014 "
         "http://www.accellera.org/XMLSchema/IPXACT/1685-2014/index.xsd\"");
}
}  // namespace

std::string ipxact_bus_definition() {
  Xml x;
  document_start(x, "busDefinition");
  x.leaf("vendor", vendor);
  x.leaf("library", bus_library);
  x.leaf("name", bus_name);
  x.leaf("version", bus_version);
  x.leaf("directConnection", "true");
  x.leaf("isAddressable", "true");
  x.leaf("maxMasters", "1");
  x.leaf("maxSlaves", "1");
  x.leaf("description",
         "TLM-2.0 (IEEE 1666) generic payload through a tlm_initiator_socket / "
         "tlm_target_socket pair, one initiator and one target per binding");
  x.close("busDefinition");
  return x.str();
}

std::string ipxact_abstraction_definition() {
  Xml x;
  document_start(x, "abstractionDefinition");
  x.leaf("vendor", vendor);
  x.leaf("library", bus_library);
  x.leaf("name", abstraction_name);
  x.leaf("version", bus_version);
  x.empty("busType", vlnv_attributes(bus_name));
  x.open("ports");
  x.open("port");
  x.leaf("logicalName", "generic_payload");
  x.leaf("description", "b_transport / nb_transport / transport_dbg of tlm::tlm_generic_payload");
  x.open("transactional");
  for (const char* side : {"onMaster", "onSlave"}) {
    x.open(side);
    x.leaf("presence", "required");
    x.leaf("initiative", std::string(side) == "onMaster" ? "requires" : "provides");
    x.leaf("busWidth", "32");
    x.close(side);
  }
  x.close("transactional");
  x.close("port");
  x.close("ports");
  x.leaf("description", "The transaction-level abstraction of tlm2_generic_payload: one "
                        "transactional port, 32 bits wide");
  x.close("abstractionDefinition");
  return x.str();
}

}  // namespace ip_export
}  // namespace specular
