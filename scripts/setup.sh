#!/usr/bin/env bash
# Install every dependency of the project from Debian 12 (bookworm) packages.
#
#   scripts/setup.sh              build, test, figures and plotting tools
#   scripts/setup.sh --gtkwave    ... and GTKWave, to open the VCD waveforms (with Xvfb,
#                                 so the tests can ask GTKWave what it shows; CI uses it)
#
# Safe to run again: apt-get skips what is already installed. Uses sudo only when not
# run as root. Non-interactive (DEBIAN_FRONTEND=noninteractive).
set -euo pipefail

# What each package is for:
#   build-essential, cmake, pkg-config  compiler and build (SystemC is found via pkg-config)
#   ninja-build                         the generator scripts/test.sh gives new build folders
#   lld                                 the linker of our targets (CMakeLists.txt, SPECULAR_USE_LLD)
#   libsystemc-dev                      SystemC 2.3.4 (kernel, TLM-2.0)
#   libgtest-dev, googletest            GoogleTest for the test suite (ctest)
#   libbenchmark-dev                    Google Benchmark for the performance study
#   graphviz                            scripts/render_figures.sh (docs/fig1.svg, fig2.svg)
#   python3-numpy, python3-matplotlib   plots of the numerical study
#   gnuplot-nox                         quick plots from the testbench's CSV output
#   clang-14, libclang-rt-14-dev        scripts/verify/sanitize.sh, fuzz.sh: libFuzzer and clang's sanitizer
#                                       runtimes (libclang_rt.fuzzer, asan, ubsan)
#   verilator, iverilog, yosys          the RTL twin (rtl/, twin/, docs/rtl.md): Verilator
#                                       5.006 compiles it into C++ models, Icarus Verilog 11
#                                       runs its Verilog testbench, Yosys 0.23 lints and
#                                       synthesises it (scripts/flows/synthesis/synth.sh)
#   qflow-tech-osu018, opensta, bc      the silicon flow (scripts/flows/synthesis/silicon.sh,
#                                       scripts/flows/gatelevel/gatesim.sh, docs/silicon.md): the
#                                       OSU 0.18 um standard cells (Liberty, Verilog models),
#                                       OpenSTA (`sta`), bc
#   qflow, graywolf, qrouter, magic,    the layout (scripts/flows/layout/layout.sh, issue 48,
#   netgen-lvs, tcsh, klayout           docs/silicon/layout.md): qflow 1.3.17's scripts (tcsh) drive graywolf
#                                       placement and qrouter routing, magic checks DRC and
#                                       extracts, netgen compares (LVS), klayout draws the die
#   nlohmann-json3-dev                  JSON: specular_tb's report settings and summary, the partial
#                                       results of sharded runs (--shard, --partial, --merge)
#   libcli11-dev                        every command's options, --help, --version and
#                                       specular_tb's --config (run_support/cli.h)
#   slurm-wlm, munge, jq                scripts/farm/farm.sh on Slurm, scripts/farm/slurm_cluster.sh
#                                       (a single-node cluster) and its test tests/farm/farm_test.sh
#                                       (jq compares the merged and unsharded JSON)
PACKAGES=(
  build-essential cmake pkg-config ninja-build
  lld
  libsystemc-dev
  libgtest-dev googletest
  libbenchmark-dev
  graphviz
  python3-numpy python3-matplotlib
  gnuplot-nox
  clang-14 libclang-rt-14-dev
  verilator iverilog yosys
  qflow-tech-osu018 opensta bc
  qflow graywolf qrouter magic netgen-lvs tcsh klayout  # scripts/flows/layout/layout.sh: place, route, DRC, LVS, the die's picture
  nlohmann-json3-dev
  libcli11-dev
  slurm-wlm munge jq
  z3  # yosys-smtbmc's solver: the AXI4-Lite properties of specular_ip_axi proved by bounded model checking (rtl/formal/, docs/rtl_ip.md)
  python3-lxml  # tests/ipxact: reads the IP-XACT component back with an XML library (docs/ipxact.md)
  # The firmware header and C driver (firmware/, tests/firmware/): cross-compiled in ctest
  # for rv32imac/ilp32 (with picolibc) and Cortex-M4 (with newlib's headers), and with
  # clang as a second host C compiler.
  gcc-riscv64-unknown-elf picolibc-riscv64-unknown-elf
  gcc-arm-none-eabi libnewlib-arm-none-eabi
  clang
  zlib1g-dev  # the twin's FST writer (Verilator --trace-fst) links zlib; the package's find_dependency(ZLIB) (issue 35)
  doxygen  # the API reference of the installed headers: target docs, test api_reference_complete (docs/api/README.md)
  python3-sphinx python3-myst-parser python3-breathe furo  # the docs as a site (Sphinx, the Markdown, the API reference, the theme): target docs_site, test docs_site (docs/conf.py)
  chromium python3-pil  # test docs_site_screenshots: the site's pages rendered headless, the pictures checked not blank, the search run
)
# gtkwave: the viewer; xvfb, xauth: a virtual X server for tests/test_vcd_waveform.cpp,
# which runs GTKWave headless (xvfb-run) with waveforms/specular.gtkw.
OPTIONAL_GTKWAVE=(gtkwave xvfb xauth)

usage() {
  sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'
}

with_gtkwave=0
for arg in "$@"; do
  case "$arg" in
    --gtkwave) with_gtkwave=1 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "setup.sh: unknown option '$arg' (allowed: --gtkwave, --help)" >&2; exit 2 ;;
  esac
done

if ! command -v apt-get >/dev/null 2>&1; then
  echo "setup.sh: apt-get not found; this script supports Debian 12 (bookworm)." >&2
  echo "setup.sh: install by hand: ${PACKAGES[*]}" >&2
  exit 1
fi
if [ -r /etc/os-release ]; then
  # shellcheck disable=SC1091
  . /etc/os-release
  if [ "${ID:-}" != "debian" ] || [ "${VERSION_ID:-}" != "12" ]; then
    echo "setup.sh: note: written for Debian 12, running on ${PRETTY_NAME:-unknown}; continuing." >&2
  fi
fi

SUDO=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    SUDO=(sudo)
  else
    echo "setup.sh: not root and sudo is not installed; run this script as root." >&2
    exit 1
  fi
fi

if [ "$with_gtkwave" -eq 1 ]; then
  PACKAGES+=("${OPTIONAL_GTKWAVE[@]}")
fi

export DEBIAN_FRONTEND=noninteractive

echo "+ apt-get update"
"${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update

echo "+ apt-get install -y --no-install-recommends ${PACKAGES[*]}"
"${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y --no-install-recommends "${PACKAGES[@]}"

echo "setup.sh: installed:"
dpkg-query -W -f='  ${Package} ${Version}\n' "${PACKAGES[@]}"
