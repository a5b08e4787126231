#include "specular/format.h"

#include <sstream>
#include <stdexcept>

namespace specular {

std::string FixedFormat::name() const {
  std::ostringstream s;
  s << (is_signed ? 'S' : 'U') << int_bits << '.' << frac_bits;
  return s.str();
}

const char* to_string(Normalisation policy) {
  switch (policy) {
    case Normalisation::patent: return "patent";
    case Normalisation::energy: return "energy";
    case Normalisation::none: return "none";
    case Normalisation::device_energy: return "device-energy";
  }
  return "?";
}

const char* to_string(Saturation policy) {
  return policy == Saturation::clamp ? "clamp" : "literal";
}

const char* to_string(Constants policy) {
  switch (policy) {
    case Constants::patent: return "patent";
    case Constants::minimax_half: return "minimax-half";
    case Constants::minimax: return "minimax";
  }
  return "?";
}

Normalisation parse_normalisation(const std::string& text) {
  if (text == "patent") return Normalisation::patent;
  if (text == "energy") return Normalisation::energy;
  if (text == "none") return Normalisation::none;
  if (text == "device-energy") return Normalisation::device_energy;
  throw std::invalid_argument("normalisation policy '" + text +
                              "' is not one of: patent, energy, none, device-energy");
}

Constants parse_constants(const std::string& text) {
  if (text == "patent") return Constants::patent;
  if (text == "minimax-half") return Constants::minimax_half;
  if (text == "minimax") return Constants::minimax;
  throw std::invalid_argument("constants policy '" + text +
                              "' is not one of: patent, minimax-half, minimax");
}

Saturation parse_saturation(const std::string& text) {
  if (text == "clamp") return Saturation::clamp;
  if (text == "literal") return Saturation::literal;
  throw std::invalid_argument("saturation policy '" + text + "' is not one of: clamp, literal");
}

namespace {
void check_width(const char* name, int value, int lo, int hi) {
  if (value < lo || value > hi) {
    std::ostringstream s;
    s << "width " << name << " = " << value << " is outside the allowed range [" << lo << ", "
      << hi << "]";
    throw std::invalid_argument(s.str());
  }
}
}  // namespace

void Widths::validate() const {
  check_width("cos_frac_bits", cos_frac_bits, 2, 30);
  check_width("n_bits", n_bits, 10, 16);  // must hold n = 1000
  check_width("rgb_bits", rgb_bits, 1, 16);
  check_width("pin19_frac_bits", pin19_frac_bits, 1, 16);
  check_width("rom5_addr_bits", rom5_addr_bits, 1, 24);
  check_width("rom5_word_bits", rom5_word_bits, 1, 31);
  check_width("reg9_int_bits", reg9_int_bits, 3, 20);
  // Multiplexer 3 aligns cos λ to register 9's format by a left shift.
  check_width("reg9_frac_bits", reg9_frac_bits, cos_frac_bits, 40);
  check_width("rom38_int_bits", rom38_int_bits, 1, 16);
  check_width("rom38_frac_bits", rom38_frac_bits, 1, 30);
  check_width("norm_int_bits", norm_int_bits, 1, 20);
  check_width("norm_frac_bits", norm_frac_bits, 1, reg9_frac_bits + rom38_frac_bits);
  check_width("out_int_bits", out_int_bits, 1, 40);
  check_width("out_frac_bits", out_frac_bits, 0, norm_frac_bits);
  if (reg9_int_bits + reg9_frac_bits > 62 || norm_int_bits + norm_frac_bits > 62 ||
      out_int_bits + out_frac_bits > 62)
    throw std::invalid_argument("a bus is wider than the 63 bits a code can carry");
}

const std::vector<WidthField>& width_fields() {
  static const std::vector<WidthField> fields = {
      {"cos_frac_bits", &Widths::cos_frac_bits},     {"n_bits", &Widths::n_bits},
      {"rgb_bits", &Widths::rgb_bits},               {"pin19_frac_bits", &Widths::pin19_frac_bits},
      {"rom5_addr_bits", &Widths::rom5_addr_bits},   {"rom5_word_bits", &Widths::rom5_word_bits},
      {"reg9_int_bits", &Widths::reg9_int_bits},     {"reg9_frac_bits", &Widths::reg9_frac_bits},
      {"rom38_int_bits", &Widths::rom38_int_bits},   {"rom38_frac_bits", &Widths::rom38_frac_bits},
      {"norm_int_bits", &Widths::norm_int_bits},     {"norm_frac_bits", &Widths::norm_frac_bits},
      {"out_int_bits", &Widths::out_int_bits},       {"out_frac_bits", &Widths::out_frac_bits}};
  return fields;
}

std::string width_names() {
  std::string names;
  for (const WidthField& field : width_fields())
    names += names.empty() ? field.name : std::string(", ") + field.name;
  return names;
}

void set_width(Widths& widths, const std::string& name, int value) {
  for (const WidthField& field : width_fields()) {
    if (name == field.name) {
      widths.*field.member = value;
      return;
    }
  }
  throw std::invalid_argument("width '" + name + "' is not one of: " + width_names());
}

namespace {
// Integer bits (no sign) that hold magnitudes up to `max_abs`.
int bits_for(long max_abs) {
  int bits = 0;
  while ((1L << bits) <= max_abs) ++bits;
  return bits;
}
}  // namespace

Formats::Formats(const Widths& w) : widths(w) {
  w.validate();
  cos = {false, 1, w.cos_frac_bits};
  n = {false, w.n_bits, 0};
  rgb = {false, w.rgb_bits, 0};
  mux4 = {false, w.n_bits, w.pin19_frac_bits};
  // ROM 5's exponent spans −F (log2 0, spec Decision; and the smallest register-9
  // code, −reg9_frac_bits) up to reg9_int_bits − 1.
  log2 = {true, bits_for(std::max(w.reg9_frac_bits, w.reg9_int_bits)), w.rom5_word_bits};
  reg9 = {true, w.reg9_int_bits, w.reg9_frac_bits};
  rom38 = {false, w.rom38_int_bits, w.rom38_frac_bits};
  norm = {true, w.norm_int_bits, w.norm_frac_bits};
  out = {true, w.out_int_bits, w.out_frac_bits};
}

namespace {
[[noreturn]] void out_of_range(const std::string& what, const std::string& value,
                               const std::string& range) {
  throw std::out_of_range(what + " = " + value + " is outside the allowed range " + range);
}
}  // namespace

code_t quantise_cos(const Formats& formats, double cos_lambda) {
  if (!(cos_lambda >= 0.0 && cos_lambda <= 1.0)) {  // also catches NaN
    std::ostringstream v;
    v.precision(17);
    v << cos_lambda;
    out_of_range("cos", v.str(), "[0, 1]");
  }
  return static_cast<code_t>(std::llround(std::ldexp(cos_lambda, formats.cos.frac_bits)));
}

code_t check_cos_code(const Formats& formats, code_t code) {
  if (code < 0 || code > formats.cos.one()) {
    std::ostringstream r;
    r << "[0, " << formats.cos.one() << "] (cos code, 1.0 = " << formats.cos.one() << ")";
    out_of_range("cos code", std::to_string(code), r.str());
  }
  return code;
}

unsigned check_n(long long n) {
  if (n < static_cast<long long>(n_min) || n > static_cast<long long>(n_max))
    out_of_range("n", std::to_string(n), "[1, 1000]");
  return static_cast<unsigned>(n);
}

unsigned check_rgb(const Formats& formats, long long intensity, const char* channel) {
  if (intensity < 0 || intensity > formats.rgb.max_code())
    out_of_range(channel, std::to_string(intensity),
                 "[0, " + std::to_string(formats.rgb.max_code()) + "]");
  return static_cast<unsigned>(intensity);
}

}  // namespace specular
