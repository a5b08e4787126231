// The installed package and the SystemC it was built with (issue 30,
// docs/integration/package.md): a consumer gets that SystemC, or a configure that stops
// with one message naming both SystemCs and the variable to set — never a link error.
//
// Each test installs this build (cmake --install) into its own scratch folder. The second
// SystemC is a fake made there: a CMake package SystemCLanguage whose library, compiled
// here, defines only the link-time check symbol of another version or C++ standard, as a
// real one does (sc_api_version_<major>_<minor>_<patch>_cxx<__cplusplus>L). What the IP
// was built with is computed from this test's own SystemC — the library this executable
// links and the standard it is compiled with, as the IP's library is — not read from the
// package.
#include <gtest/gtest.h>

#include <systemc>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include "support/installed_package.h"
#include "support/scratch.h"
#include "support/subprocess.h"

namespace fs = std::filesystem;

namespace {

using specular::testing_support::cache_value;
using specular::testing_support::cmake;
using specular::testing_support::install;
using specular::testing_support::Outcome;
using specular::testing_support::run_command;
using specular::testing_support::scratch_subdir;
using specular::testing_support::shell_quoted;
using specular::testing_support::slurp;


void write_file(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

/// A SystemC as its link check names it.
struct Systemc {
  unsigned major, minor, patch;
  long cplusplus;  ///< __cplusplus of the standard its library was built for
  std::string version() const {
    return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
  }
  std::string api() const {
    return "sc_api_version_" + std::to_string(major) + "_" + std::to_string(minor) + "_" +
           std::to_string(patch) + "_cxx" + std::to_string(cplusplus) + "L";
  }
  std::string standard() const { return "C++" + std::to_string(cplusplus / 100 % 100); }
};

/// The SystemC this executable links: its library's check symbol is this one, or the link
/// of this test (compiled as the IP is) would have failed.
Systemc this_systemc() {
  return {sc_core::sc_version_major, sc_core::sc_version_minor, sc_core::sc_version_patch,
          static_cast<long>(__cplusplus)};
}
Systemc other_version() {
  const Systemc own = this_systemc();
  return own.major == 3 ? Systemc{2, 3, 4, own.cplusplus} : Systemc{3, 0, 2, own.cplusplus};
}
Systemc other_standard() {
  Systemc s = this_systemc();
  s.cplusplus = s.cplusplus == 202002L ? 201703L : 202002L;
  return s;
}

fs::path config_file(const fs::path& prefix) {
  for (const char* lib : {"lib", "lib64", "lib/x86_64-linux-gnu"})
    if (fs::exists(prefix / lib / "cmake/SpecularUnit/SpecularUnitConfig.cmake"))
      return prefix / lib / "cmake/SpecularUnit/SpecularUnitConfig.cmake";
  ADD_FAILURE() << "no SpecularUnitConfig.cmake under " << prefix;
  return {};
}

/// What the installed package recorded: set(SpecularUnit_SYSTEMC_<name> "<value>").
std::string recorded(const fs::path& prefix, const std::string& name) {
  std::smatch m;
  const std::string config = slurp(config_file(prefix));
  if (!std::regex_search(config, m, std::regex("set\\(SpecularUnit_SYSTEMC_" + name + " \"([^\"]*)\"\\)")))
    return "<not recorded>";
  return m[1].str();
}

/// The installed package's record rewritten to say it was built with `s`, a CMake
/// package at `dir`: a build made with a SystemC this machine may not have.
void rewrite_record(const fs::path& prefix, const Systemc& s, const fs::path& dir,
                    const std::string& found_by = "CMake package") {
  const fs::path config = config_file(prefix);
  std::string text = slurp(config);
  const auto rewrite = [&text](const std::string& name, const std::string& value) {
    const std::regex line("set\\(SpecularUnit_SYSTEMC_" + name + " \"[^\"]*\"\\)");
    ASSERT_TRUE(std::regex_search(text, line)) << name;
    text = std::regex_replace(text, line, "set(SpecularUnit_SYSTEMC_" + name + " \"" + value + "\")");
  };
  rewrite("FOUND_BY", found_by);
  rewrite("LOCATION", dir.string());
  rewrite("VERSION", s.version());
  rewrite("CXX", std::to_string(s.cplusplus / 100 % 100));
  rewrite("API", s.api());
  write_file(config, text);
}

/// A fake SystemC `s` under `root`: headers, a library defining only its check symbol,
/// and Accellera's CMake package files. Returns its SystemCLanguage_DIR.
fs::path fake_systemc(const fs::path& root, const Systemc& s) {
  const std::string symbol = s.api();
  fs::create_directories(root / "lib");
  write_file(root / "fake.cpp", "namespace sc_core { struct " + symbol + " { " + symbol + "(); };\n" +
                                    symbol + "::" + symbol + "() {} }\n");
  const Outcome built = run_command(shell_quoted(cache_value("CMAKE_CXX_COMPILER")) +
                                        " -shared -fPIC -o " + shell_quoted(root / "lib/libsystemc.so") +
                                        " " + shell_quoted(root / "fake.cpp"),
                                    root, "compile");
  EXPECT_EQ(built.status, 0) << built.err;
  write_file(root / "include/sysc/kernel/sc_ver.h",
             "#define SC_VERSION_MAJOR " + std::to_string(s.major) + "\n#define SC_VERSION_MINOR " +
                 std::to_string(s.minor) + "\n#define SC_VERSION_PATCH " + std::to_string(s.patch) + "\n");
  const fs::path dir = root / "lib/cmake/SystemCLanguage";
  write_file(dir / "SystemCLanguageConfig.cmake",
             "get_filename_component(_root \"${CMAKE_CURRENT_LIST_DIR}/../../..\" ABSOLUTE)\n"
             "if(NOT TARGET SystemC::systemc)\n"
             "  add_library(SystemC::systemc SHARED IMPORTED)\n"
             "  set_target_properties(SystemC::systemc PROPERTIES\n"
             "    IMPORTED_LOCATION \"${_root}/lib/libsystemc.so\"\n"
             "    INTERFACE_INCLUDE_DIRECTORIES \"${_root}/include\")\n"
             "endif()\n");
  write_file(dir / "SystemCLanguageConfigVersion.cmake",
             "set(PACKAGE_VERSION " + s.version() + ")\nset(PACKAGE_VERSION_COMPATIBLE TRUE)\n");
  return dir;
}

/// The same fake `s` under `root`, found by pkg-config: a systemc.pc naming its library
/// and headers, as Debian's libsystemc-dev has. Returns the folder of systemc.pc.
fs::path fake_systemc_pc(const fs::path& root, const Systemc& s) {
  fake_systemc(root, s);
  write_file(root / "pkgconfig/systemc.pc",
             "prefix=" + root.string() + "\nlibdir=${prefix}/lib\nincludedir=${prefix}/include\n"
             "Name: SystemC\nDescription: fake\nVersion: " + s.version() +
                 "\nLibs: -L${libdir} -lsystemc\nCflags: -I${includedir}\n");
  return root / "pkgconfig";
}

/// A SoC project using the package; with -DOWN_SYSTEMC=ON it finds a SystemC of its own
/// first, with -DBUILD_IT=ON it builds and links a program using the IP.
fs::path consumer_source(const fs::path& dir) {
  const fs::path source = dir / "consumer";
  write_file(source / "CMakeLists.txt",
             "cmake_minimum_required(VERSION 3.16)\n"
             "project(consumer LANGUAGES CXX)\n"
             "set(CMAKE_CXX_STANDARD " + std::to_string(__cplusplus / 100 % 100) + ")\n"
             "set(CMAKE_CXX_STANDARD_REQUIRED ON)\n"
             "if(OWN_SYSTEMC)\n"
             "  find_package(SystemCLanguage CONFIG REQUIRED)\n"
             "endif()\n"
             "if(OWN_PC_TARGET)  # its own SystemC::systemc, from pkg-config's systemc.pc\n"
             "  find_package(PkgConfig REQUIRED)\n"
             "  pkg_check_modules(OWN REQUIRED IMPORTED_TARGET systemc)\n"
             "  add_library(SystemC::systemc INTERFACE IMPORTED)\n"
             "  target_link_libraries(SystemC::systemc INTERFACE PkgConfig::OWN)\n"
             "endif()\n"
             "find_package(SpecularUnit CONFIG REQUIRED)\n"
             "if(BUILD_IT)\n"
             "  add_executable(consumer main.cpp)\n"
             "  target_link_libraries(consumer PRIVATE SpecularUnit::specular)\n"
             "endif()\n"
             "if(SECOND_SYSTEMC)  # its own pkg-config SystemC linked beside the package's\n"
             "  find_package(PkgConfig REQUIRED)\n"
             "  pkg_check_modules(SECOND REQUIRED systemc)\n"
             "  add_executable(mixed main.cpp)\n"
             "  target_link_libraries(mixed PRIVATE SpecularUnit::specular ${SECOND_LINK_LIBRARIES})\n"
             "endif()\n");
  write_file(source / "main.cpp",
             "#include <specular/specular.h>\n"
             "#include <cstdio>\n"
             "int sc_main(int, char*[]) {\n"
             "  specular::SpecularLtTarget ip(\"ip\");  // the IP's library, linked\n"
             "  std::printf(\"%u.%u.%u\\n\", sc_core::sc_version_major, sc_core::sc_version_minor,\n"
             "              sc_core::sc_version_patch);\n"
             "  return 0;\n"
             "}\n");
  return source;
}

/// A sanitized build's library needs the sanitizers' runtime in a consumer's link too:
/// the `-D`s that give it, or nothing for a plain build.
std::string sanitizer_flags() {
  const std::string sanitize = cache_value("SPECULAR_SANITIZE");
  return sanitize == "ON" || sanitize == "TRUE" || sanitize == "1"
             ? " '-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined'"
               " '-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined'"
             : "";
}

Outcome configure(const fs::path& dir, const std::string& arguments, const std::string& environment = "") {
  return run_command(environment + cmake() + " -S " + shell_quoted(consumer_source(dir)) + " -B " +
                         shell_quoted(dir / "build") + " -DCMAKE_BUILD_TYPE=Release" +
                         sanitizer_flags() + " " + arguments,
                     dir, "configure");
}

/// The configure stopped at find_package(SpecularUnit) with exactly one error.
void expect_one_refusal(const Outcome& r) {
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_NE(r.err.find("SpecularUnit_FOUND to FALSE"), std::string::npos) << r.err;
  std::size_t errors = 0;
  for (std::size_t at = r.err.find("CMake Error"); at != std::string::npos;
       at = r.err.find("CMake Error", at + 1))
    ++errors;
  EXPECT_EQ(errors, 1u) << r.err;
}

/// The step of the advice that gives the package its recorded SystemC (issue 35), for a
/// project whose SystemCLanguage_DIR is `dir_set` ("" when unset): by the record's route.
std::string expected_fix(const fs::path& prefix, const std::string& dir_set) {
  const std::string at = recorded(prefix, "LOCATION");
  if (recorded(prefix, "FOUND_BY") == "CMake package")
    return "set SystemCLanguage_DIR=" + at + " (cmake -DSystemCLanguage_DIR=" + at + ")";
  if (dir_set.empty()) return "set the environment variable PKG_CONFIG_PATH=" + at;
  return "unset SystemCLanguage_DIR (cmake -U SystemCLanguage_DIR; it is " + dir_set +
         " and is used before pkg-config) and set the environment variable PKG_CONFIG_PATH=" + at;
}

/// CMake wraps a message's lines: compare with spaces and line breaks as one space.
std::string flat(const std::string& text) {
  return std::regex_replace(text, std::regex("[ \n]+"), " ");
}

TEST(PackageSystemC, RecordsTheSystemCItWasBuiltWith) {
  const fs::path prefix = install(scratch_subdir("run"));
  const Systemc own = this_systemc();
  EXPECT_EQ(recorded(prefix, "API"), own.api());
  EXPECT_EQ(recorded(prefix, "VERSION"), own.version());
  EXPECT_EQ(recorded(prefix, "CXX"), std::to_string(own.cplusplus / 100 % 100));
  const std::string by = recorded(prefix, "FOUND_BY");
  EXPECT_TRUE(by == "CMake package" || by == "pkg-config") << by;
  EXPECT_TRUE(fs::is_directory(recorded(prefix, "LOCATION"))) << recorded(prefix, "LOCATION");
}

TEST(PackageSystemC, TheSameSystemCConfiguresBuildsLinksAndRuns) {
  const fs::path dir = scratch_subdir("run");
  const fs::path prefix = install(dir);
  const Systemc own = this_systemc();
  const Outcome r = configure(dir, "-DBUILD_IT=ON -DCMAKE_PREFIX_PATH=" + shell_quoted(prefix));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("SpecularUnit: SystemC " + own.version() + " for " + own.standard() +
                       " (" + own.api() + ", "),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("the one it was built with"), std::string::npos) << r.out;
  const Outcome built = run_command(cmake() + " --build " + shell_quoted(dir / "build") + " -j 2", dir, "build");
  ASSERT_EQ(built.status, 0) << built.out << built.err;
  const Outcome ran = run_command("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 " + shell_quoted(dir / "build/consumer"), dir);
  EXPECT_EQ(ran.status, 0) << ran.err;
  EXPECT_EQ(ran.out, own.version() + "\n");
}

TEST(PackageSystemC, FindsTheSystemCItWasBuiltWithBeforeAnotherFirstOnThePath) {
  const fs::path dir = scratch_subdir("run");
  const fs::path prefix = install(dir);
  fake_systemc(dir / "other", other_version());
  const Outcome r = configure(dir, "-DCMAKE_PREFIX_PATH=" + shell_quoted((dir / "other").string() + ";" +
                                                                  prefix.string()));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("SpecularUnit: SystemC " + this_systemc().version() + " for " +
                       this_systemc().standard() + " (" + this_systemc().api() + ", "),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find(other_version().api()), std::string::npos) << r.out;
}

TEST(PackageSystemC, RefusesAConsumersOwnSystemCOfAnotherVersion) {
  const fs::path dir = scratch_subdir("run");
  const fs::path prefix = install(dir);
  const Systemc own = this_systemc(), other = other_version();
  const fs::path other_dir = fake_systemc(dir / "other", other);
  const Outcome r = configure(dir, "-DOWN_SYSTEMC=ON -DCMAKE_PREFIX_PATH=" +
                                       shell_quoted((dir / "other").string() + ";" + prefix.string()));
  expect_one_refusal(r);
  const std::string message = flat(r.err);
  EXPECT_NE(message.find("built with SystemC " + own.version() + " for " + own.standard() + " (" +
                         own.api()),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("this project's SystemC is " + other.version() + " for " +
                         other.standard() + " (" + other.api() + ", CMake package at " +
                         other_dir.string() + ")"),
            std::string::npos)
      << message;
  // The whole fix: the project's own SystemC::systemc first, then the record's route.
  EXPECT_NE(message.find("this project makes SystemC::systemc itself before find_package(SpecularUnit) "
                         "(by find_package(SystemCLanguage) at " + other_dir.string() +
                         "): make it from that SystemC, or call find_package(SpecularUnit) first, "
                         "which then makes it; " + expected_fix(prefix, other_dir.string())),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("rebuild SpecularUnit with SystemC " + other.version()), std::string::npos)
      << message;
}

TEST(PackageSystemC, RefusesSystemCLanguageDirOfTheSameVersionBuiltForAnotherStandard) {
  const fs::path dir = scratch_subdir("run");
  const fs::path prefix = install(dir);
  const Systemc own = this_systemc(), other = other_standard();
  const fs::path other_dir = fake_systemc(dir / "other", other);
  const Outcome r = configure(dir, "-DCMAKE_PREFIX_PATH=" + shell_quoted(prefix) +
                                       " -DSystemCLanguage_DIR=" + shell_quoted(other_dir));
  expect_one_refusal(r);
  const std::string message = flat(r.err);
  EXPECT_NE(message.find(own.version() + " for " + own.standard() + " (" + own.api()),
            std::string::npos)
      << message;
  EXPECT_NE(message.find(other.version() + " for " + other.standard() + " (" + other.api()),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("Give it SystemC " + own.version() + " built for " + own.standard() + ": " +
                         expected_fix(prefix, other_dir.string()) + "; or rebuild"),
            std::string::npos)
      << message;
}

// Built with a SystemC CMake package (here a fake, the record rewritten to name it), consumed
// naming only the package's prefix: the package finds that one, not the machine's own.
TEST(PackageSystemC, FindsTheRecordedCMakePackageBeforeTheMachinesOwnSystemC) {
  const fs::path dir = scratch_subdir("run");
  const fs::path prefix = install(dir);
  const Systemc built = other_version();
  const fs::path built_dir = fake_systemc(dir / "built", built);
  rewrite_record(prefix, built, built_dir);
  const Outcome r = configure(dir, "-DCMAKE_PREFIX_PATH=" + shell_quoted(prefix));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("SpecularUnit: SystemC " + built.version() + " for " + built.standard() +
                       " (" + built.api() + ", CMake package at " + built_dir.string() +
                       "), the one it was built with"),
            std::string::npos)
      << r.out;
}

// The issue's case: built with a SystemC this machine no longer has (the record rewritten
// to name one at a folder that does not exist); the package finds another, here a fake
// first on CMAKE_PREFIX_PATH, so that the test does not depend on which SystemC the
// machine finds by default (issue 35: on a build against 3.0.2 that was Debian's 2.3.4,
// of the same check symbol as the record's "other" version).
TEST(PackageSystemC, RefusesTheSystemCItFindsWhenTheOneItWasBuiltWithIsGone) {
  const fs::path dir = scratch_subdir("run");
  const fs::path prefix = install(dir);
  const Systemc gone = other_version(), found = other_standard();
  const fs::path gone_dir = dir / "gone/lib/cmake/SystemCLanguage";
  rewrite_record(prefix, gone, gone_dir);
  const fs::path found_dir = fake_systemc(dir / "found", found);
  const Outcome r = configure(dir, "-DCMAKE_PREFIX_PATH=" + shell_quoted((dir / "found").string() + ";" +
                                                                  prefix.string()));
  expect_one_refusal(r);
  const std::string message = flat(r.err);
  EXPECT_NE(message.find("built with SystemC " + gone.version() + " for " + gone.standard() +
                         " (" + gone.api() + ", CMake package at " + gone_dir.string() + ")"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("this project's SystemC is " + found.version() + " for " + found.standard() +
                         " (" + found.api() + ", CMake package at " + found_dir.string() + ")"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("it is no longer at " + gone_dir.string() + ": install it there again, or "
                         "point to where it is now with SystemCLanguage_DIR="),
            std::string::npos)
      << message;
}

// Issue 35: the project makes SystemC::systemc itself from pkg-config while a
// SystemCLanguage_DIR naming the package's SystemC is set. The message names the
// target's own library as this project's SystemC (not SystemCLanguage_DIR's folder) and
// says that the project's own target is the thing to change.
TEST(PackageSystemC, NamesTheProjectsOwnTargetsLibraryNotALeftoverSystemCLanguageDir) {
  const fs::path dir = scratch_subdir("run");
  const fs::path prefix = install(dir);
  const Systemc built = other_version(), own_target = this_systemc();
  const fs::path built_dir = fake_systemc(dir / "built", built);
  rewrite_record(prefix, built, built_dir);
  const fs::path pc_dir = fake_systemc_pc(dir / "pc", own_target);
  const Outcome r = configure(dir,
                              "-DOWN_PC_TARGET=ON -DSystemCLanguage_DIR=" + shell_quoted(built_dir) +
                                  " -DCMAKE_PREFIX_PATH=" + shell_quoted(prefix),
                              "PKG_CONFIG_PATH=" + shell_quoted(pc_dir) + " ");
  expect_one_refusal(r);
  const std::string message = flat(r.err);
  EXPECT_NE(message.find("this project's SystemC is " + own_target.version() + " for " +
                         own_target.standard() + " (" + own_target.api() +
                         ", this project's own SystemC::systemc target, library " +
                         (dir / "pc/lib/libsystemc.so").string() + ")"),
            std::string::npos)
      << message;
  EXPECT_EQ(message.find(own_target.api() + ", CMake package at"), std::string::npos) << message;
  EXPECT_NE(message.find("this project makes SystemC::systemc itself before find_package(SpecularUnit) "
                         "(not by SpecularUnit): make it from that SystemC, or call "
                         "find_package(SpecularUnit) first, which then makes it; set "
                         "SystemCLanguage_DIR=" + built_dir.string()),
            std::string::npos)
      << message;
}

// Issue 35: built with a pkg-config SystemC, consumed with a SystemCLanguage_DIR set to
// another: the advice says to unset SystemCLanguage_DIR as well as where systemc.pc is,
// and following it (in the same build folder) configures with the recorded SystemC.
TEST(PackageSystemC, TheAdviceUnsetsSystemCLanguageDirAndFollowingItConfigures) {
  const fs::path dir = scratch_subdir("run");
  const fs::path prefix = install(dir);
  const Systemc built = other_version(), other = other_standard();
  const fs::path pc_dir = fake_systemc_pc(dir / "built", built);
  rewrite_record(prefix, built, pc_dir, "pkg-config");
  const fs::path other_dir = fake_systemc(dir / "other", other);
  const Outcome r = configure(dir, "-DSystemCLanguage_DIR=" + shell_quoted(other_dir) +
                                       " -DCMAKE_PREFIX_PATH=" + shell_quoted(prefix));
  expect_one_refusal(r);
  const std::string message = flat(r.err);
  const std::string advice = "unset SystemCLanguage_DIR (cmake -U SystemCLanguage_DIR; it is " +
                             other_dir.string() + " and is used before pkg-config) and set the "
                             "environment variable PKG_CONFIG_PATH=" + pc_dir.string();
  ASSERT_NE(message.find("Give it SystemC " + built.version() + " built for " + built.standard() +
                         ": " + advice),
            std::string::npos)
      << message;
  // Followed: -U SystemCLanguage_DIR and PKG_CONFIG_PATH, the same build folder.
  const Outcome again = configure(dir, "-U SystemCLanguage_DIR -DCMAKE_PREFIX_PATH=" + shell_quoted(prefix),
                                  "PKG_CONFIG_PATH=" + shell_quoted(pc_dir) + " ");
  ASSERT_EQ(again.status, 0) << again.out << again.err;
  EXPECT_NE(again.out.find("SpecularUnit: SystemC " + built.version() + " for " + built.standard() +
                           " (" + built.api() + ", pkg-config at " + pc_dir.string() +
                           "), the one it was built with"),
            std::string::npos)
      << again.out;
}

// Issue 35: a program that links its own pkg-config SystemC beside the package's (a
// second libsystemc, which crashes in static initialisation) is refused at configure time,
// naming the target and both libraries.
TEST(PackageSystemC, RefusesAProgramLinkingASecondSystemCBesideThePackages) {
  const fs::path dir = scratch_subdir("run");
  const fs::path prefix = install(dir);
  const fs::path pc_dir = fake_systemc_pc(dir / "second", other_version());
  // The package's own SystemC by its record; the project's second one by PKG_CONFIG_PATH.
  const Outcome r = configure(dir, "-DSECOND_SYSTEMC=ON -DCMAKE_PREFIX_PATH=" + shell_quoted(prefix),
                              "PKG_CONFIG_PATH=" + shell_quoted(pc_dir) + " ");
  EXPECT_NE(r.status, 0) << r.out;
  const std::string message = flat(r.err);
  EXPECT_NE(message.find("Target mixed ("), std::string::npos) << message;
  EXPECT_NE(message.find("and another SystemC library beside it: " +
                         (dir / "second/lib/libsystemc.so").string() + "."),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("Link only SystemC::systemc, the one SpecularUnit gives"), std::string::npos)
      << message;
}

// ---- issue 35: the core component on a host where no SystemC can be found ------------

/// `env` and `-D`s that hide every SystemC from one configure: pkg-config searches only an
/// empty folder, and find_package(SystemCLanguage) is disabled.
struct NoSystemC {
  std::string environment, arguments;
};
NoSystemC no_systemc(const fs::path& dir) {
  fs::create_directories(dir / "empty");
  return {"PKG_CONFIG_LIBDIR=" + shell_quoted(dir / "empty") + " PKG_CONFIG_PATH= SystemCLanguage_DIR= ",
          " -DCMAKE_DISABLE_FIND_PACKAGE_SystemCLanguage=ON"};
}

TEST(PackageCore, APlainMainOnCoreConfiguresBuildsAndRunsWhereNoSystemCCanBeFound) {
  const fs::path dir = scratch_subdir("run");
  const fs::path prefix = install(dir);
  const NoSystemC hidden = no_systemc(dir);
  // The hiding works: pkg-config finds no systemc.pc with it.
  EXPECT_NE(run_command(hidden.environment + "pkg-config --exists systemc", dir, "probe").status, 0);
  const Outcome r = run_command(
      hidden.environment + cmake() + " -S " + shell_quoted(fs::path(SPECULAR_SOURCE_DIR) / "examples/consumer") +
          " -B " + shell_quoted(dir / "build") + " -DCMAKE_BUILD_TYPE=Release -DSPECULAR_CONSUMER_CORE_ONLY=ON" +
          " -DCMAKE_PREFIX_PATH=" + shell_quoted(prefix) + sanitizer_flags() + hidden.arguments,
      dir, "configure");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("sc_api_version"), std::string::npos) << "no SystemC is looked for:\n" << r.out;
  EXPECT_EQ(r.out.find("SpecularUnit: SystemC"), std::string::npos) << r.out;
  const Outcome built = run_command(cmake() + " --build " + shell_quoted(dir / "build") + " -j 2", dir, "build");
  ASSERT_EQ(built.status, 0) << built.out << built.err;
  const Outcome ran = run_command(shell_quoted(dir / "build/consumer_core"), dir);
  EXPECT_EQ(ran.status, 0) << ran.out << ran.err;
  EXPECT_NE(ran.out.find("outputs of Core within the documented bound of the double formula: PASS"),
            std::string::npos)
      << ran.out;
}

// Asking for the SystemC targets there (no component, or COMPONENTS specular) stops the
// configure with one message: which SystemC is missing, how to give it, and the core
// component. The record is rewritten to a folder that does not exist, as on a host
// other than the build's.
TEST(PackageCore, AskingForTheSystemCTargetsWhereNoneCanBeFoundIsOneClearRefusal) {
  const fs::path dir = scratch_subdir("run");
  const fs::path prefix = install(dir);
  const Systemc built = this_systemc();
  const fs::path gone = dir / "gone/pkgconfig";
  rewrite_record(prefix, built, gone, "pkg-config");
  const NoSystemC hidden = no_systemc(dir);
  for (const std::string components : {"", " COMPONENTS specular"}) {
    write_file(dir / "asks/CMakeLists.txt", "cmake_minimum_required(VERSION 3.16)\n"
                                            "project(asks LANGUAGES CXX)\n"
                                            "find_package(SpecularUnit CONFIG REQUIRED" + components + ")\n");
    fs::remove_all(dir / "asks/build");
    const Outcome r = run_command(hidden.environment + cmake() + " -S " + shell_quoted(dir / "asks") + " -B " +
                                      shell_quoted(dir / "asks/build") + " -DCMAKE_PREFIX_PATH=" +
                                      shell_quoted(prefix) + hidden.arguments,
                                  dir, "configure");
    SCOPED_TRACE("find_package(SpecularUnit CONFIG REQUIRED" + components + ")");
    expect_one_refusal(r);
    const std::string message = flat(r.err);
    EXPECT_NE(message.find("SpecularUnit was built with SystemC " + built.version() + " for " +
                           built.standard() + " (" + built.api() + ", pkg-config at " + gone.string() +
                           "), and no SystemC found: neither Accellera's CMake package SystemCLanguage "
                           "nor pkg-config's systemc.pc."),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("For SpecularUnit::specular and ::twin: it is no longer at " + gone.string()),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("For SpecularUnit::core alone, which needs no SystemC: "
                           "find_package(SpecularUnit COMPONENTS core)"),
              std::string::npos)
        << message;
  }
}

// The IP's own build: a SystemC built for another standard than the IP's stops the configure.
TEST(PackageSystemC, TheBuildRefusesASystemCBuiltForAnotherStandard) {
  const fs::path dir = scratch_subdir("run");
  const Systemc other = other_standard();
  const fs::path other_dir = fake_systemc(dir / "other", other);
  const Outcome r = run_command(cmake() + " -S " + shell_quoted(SPECULAR_SOURCE_DIR) + " -B " +
                                    shell_quoted(dir / "build") + " -DSystemCLanguage_DIR=" +
                                    shell_quoted(other_dir),
                                dir, "configure");
  EXPECT_NE(r.status, 0) << r.out;
  const std::string message = flat(r.err);
  EXPECT_NE(message.find("its library was built for " + other.standard() +
                         ", and SpecularUnit is compiled as " + this_systemc().standard() +
                         " (CMAKE_CXX_STANDARD)"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find(other.api()), std::string::npos) << message;
}

}  // namespace
