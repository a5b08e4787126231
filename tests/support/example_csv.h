// waveforms/example.csv, written out again for the waveform tests (test_vcd_waveform.cpp,
// test_rtl_vcd.cpp): the operations whose traces they check, one per start.
#pragma once

#include <vector>

namespace specular {
namespace testing_support {

/// One line of the file: cos, n, R, G, B.
struct Example {
  double cos;
  int n;
  int rgb[3];
};

inline const std::vector<Example> examples = {{0.9, 10, {200, 100, 50}},
                                              {0.95, 10, {200, 100, 50}},
                                              {1, 10, {200, 100, 50}},
                                              {0.99, 100, {255, 128, 0}}};

}  // namespace testing_support
}  // namespace specular
