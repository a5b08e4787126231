// specular_variant_error: a design variant's exhaustive error (variant_error.h).
#include <iostream>
#include <string>
#include <vector>

#include "variant_error.h"

int main(int argc, char** argv) {
  return specular::tb::run_variant_error(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
