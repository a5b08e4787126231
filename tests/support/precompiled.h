// The headers nearly every test includes, parsed once per build: GoogleTest, SystemC
// and TLM-2.0 take 2-4 s of each test's compile (about a third of it under the
// sanitizers), so tests/CMakeLists.txt precompiles them in specular_test_main and every
// test reuses that (CI budget, docs/testing.md). Only third-party headers go here: a
// test's own includes still say what it uses.
#ifndef SPECULAR_TESTS_SUPPORT_PRECOMPILED_H
#define SPECULAR_TESTS_SUPPORT_PRECOMPILED_H

#include <gtest/gtest.h>

#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/simple_target_socket.h>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#endif  // SPECULAR_TESTS_SUPPORT_PRECOMPILED_H
