#!/bin/sh
# setup.sh: install the Debian packages uasimpact needs, only those that are missing.
# 'setup.sh test' adds what make check needs beyond the build: python3-pandas
# (tests/app/case/test_output.sh reads every export with pandas.read_csv's default arguments).
# Called by the Makefile (make deps, run, check); safe to run again; prints nothing when all is there.
# 'setup.sh fuzz' adds what make fuzz needs (clang, libFuzzer); 'setup.sh san' what make
# check-san needs (valgrind; the sanitizer runtimes come with gcc); 'setup.sh tsan' the
# ThreadSanitizer runtime of make check-tsan; 'setup.sh mpi' OpenMPI for make mpi (make check
# and make bench build it: the comparison of MPI runs with serial ones is part of the tests);
# 'setup.sh browser' headless Chromium, which tests/test_report.sh uses to render a report
# (skipped without it).
set -e

pkgs="gcc make pkg-config libgsl-dev libncurses-dev libreadline-dev libcmocka-dev libxml2-dev libjansson-dev gnuplot-nox tmux"
case "$1" in
  fuzz) pkgs="$pkgs clang libclang-rt-dev" ;;
  san) pkgs="$pkgs valgrind" ;;
  tsan) pkgs="$pkgs libtsan2" ;;
  mpi) pkgs="$pkgs libopenmpi-dev openmpi-bin" ;;
  browser) pkgs="$pkgs chromium" ;;
  test) pkgs="$pkgs python3-pandas" ;;
esac
[ -n "$UASIMPACT_EXTRA_PKGS" ] && pkgs="$pkgs $UASIMPACT_EXTRA_PKGS"

missing=""
for p in $pkgs; do
  st=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  case "$st" in
    *"install ok installed"*) ;;
    *) missing="$missing $p" ;;
  esac
done
[ -z "$missing" ] && exit 0

echo "setup: installing missing Debian packages:$missing"
if [ "$(id -u)" -eq 0 ]; then SUDO=""; else SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
# shellcheck disable=SC2086
$SUDO apt-get install -y -qq --no-install-recommends $missing >/dev/null
echo "setup: done"
