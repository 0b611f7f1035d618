# test_install.sh: make install and make uninstall as a Debian package would use them (the
# Makefile, src/app/base/datadir.c): into a scratch PREFIX, the program runs the tour from another
# folder (source tour.ses, model load quad.urm found under PREFIX/share/uasimpact after the
# current folder); a program built on the installed headers, pkg-config file and shared library
# runs and needs the library by its soname; DESTDIR stages the same tree with the final PREFIX
# in the pkg-config file; uninstall leaves nothing behind; make run and make check build in
# parallel.
. tests/lib.sh

P=$TMP/prefix
make -s install PREFIX="$P" >"$TMP/make" 2>&1
check install_status cond '[ $? -eq 0 ] || { cat "$TMP/make"; false; }'
check install_tree cond '[ -x "$P/bin/uasimpact" ] && [ -s "$P/lib/libuasimpact.a" ] &&
  [ -f "$P/lib/libuasimpact.so.0.1" ] && [ "$(readlink "$P/lib/libuasimpact.so.0")" = libuasimpact.so.0.1 ] &&
  [ "$(readlink "$P/lib/libuasimpact.so")" = libuasimpact.so.0 ] &&
  [ -s "$P/lib/pkgconfig/uasimpact.pc" ] && [ -s "$P/include/uasimpact/engine.h" ] &&
  [ -s "$P/share/man/man1/uasimpact.1" ] && [ -s "$P/share/man/man5/uasimpact-model.5" ] &&
  [ -s "$P/share/man/man7/uasimpact-injury.7" ] && [ -s "$P/share/uasimpact/sessions/tour.ses" ] &&
  [ -s "$P/share/uasimpact/sessions/quad/quad.urm" ] &&
  [ -s "$P/share/uasimpact/sessions/paper/grids/table04_caseA_wind0.csv" ]'
if [ -x uasimpact-mpi ]; then
  check install_mpi [ -x "$P/bin/uasimpact-mpi" ]
else
  skip install_mpi "uasimpact-mpi is not built (make mpi)"
fi
if command -v readelf >/dev/null 2>&1; then
  check soname cond 'readelf -d "$P/lib/libuasimpact.so.0.1" | grep -q "SONAME.*\[libuasimpact.so.0\]"'
fi

# the tour from another folder, and the example quadcopter by its name alone
mkdir -p "$TMP/elsewhere"
(cd "$TMP/elsewhere" && "$P/bin/uasimpact" -c 'source tour.ses' >"$TMP/tour" 2>"$TMP/tour.err")
check tour_from_elsewhere cond '[ $? -eq 0 ] && grep -q "case B" "$TMP/tour" || { cat "$TMP/tour.err"; false; }'
(cd "$TMP/elsewhere" && "$P/bin/uasimpact" -c 'model drop airbags; model drop ra3; model load quad.urm; model parts' \
  >"$TMP/quad" 2>&1)
check model_by_name cond '[ $? -eq 0 ] && grep -q "share/uasimpact/sessions/quad/quad.urm" "$TMP/quad" || { cat "$TMP/quad"; false; }'
# a session that loads its model by its path in the repository (sessions/quad/quad.urm)
(cd "$TMP/elsewhere" && "$P/bin/uasimpact" quad.ses >"$TMP/quadses" 2>&1)
check quad_session cond '[ $? -eq 0 ] || { cat "$TMP/quadses"; false; }'
# the current folder comes first
printf 'show step\n' >"$TMP/elsewhere/tour.ses"
(cd "$TMP/elsewhere" && "$P/bin/uasimpact" -c 'set step 0.3; source tour.ses' >"$TMP/own" 2>&1)
check current_folder_first cond '[ "$(cat "$TMP/own")" = "step             0.3 m" ] || { cat "$TMP/own"; false; }'
(cd "$TMP/elsewhere" && "$P/bin/uasimpact" -c 'source nosuch.ses' >"$TMP/no" 2>&1)
check missing_named has "$TMP/no" "cannot open 'nosuch.ses': No such file or directory"
# the program run from its build folder has no data folder: a name alone is not found there
(cd "$TMP/elsewhere" && "$OLDPWD/uasimpact" -c 'model load quad.urm' >"$TMP/build" 2>&1)
check build_tree_no_data has "$TMP/build" "cannot open 'quad.urm'"

# a program on the installed library: pkg-config, the headers, the shared library by soname;
# the descent at zero wind is the paper's Table 2 (case B's column, 7.48 m/s), as the program says
if command -v pkg-config >/dev/null 2>&1; then
  cat >"$TMP/use.c" <<'C'
#include <stdio.h>
#include <uasimpact/descent.h>
int main(void) {
  urDescentParams p;
  urDescentResult r;
  char err[200];
  ur_descent_defaults(&p);
  p.wind = 0;
  if (ur_descent(&p, &r, err, sizeof err)) return 1;
  printf("%.3f\n", r.speed);
  return 0;
}
C
  PKG_CONFIG_PATH="$P/lib/pkgconfig" cc -o "$TMP/use" "$TMP/use.c" \
    $(PKG_CONFIG_PATH="$P/lib/pkgconfig" pkg-config --cflags --libs uasimpact) -lgsl -lgslcblas -lm \
    2>"$TMP/cc"
  check pkgconfig_builds cond '[ $? -eq 0 ] || { cat "$TMP/cc"; false; }'
  check needs_soname cond 'readelf -d "$TMP/use" | grep -q "NEEDED.*\[libuasimpact.so.0\]"'
  LD_LIBRARY_PATH="$P/lib" "$TMP/use" >"$TMP/use.out"
  check shared_runs cond '[ "$(cat "$TMP/use.out")" = 7.480 ] &&
    "$P/bin/uasimpact" -c descent | awk "NR==2 && \$3 == \"7.480\" {ok=1} END {exit !ok}"'
else
  skip pkgconfig_builds "pkg-config is not installed"
fi

# DESTDIR: the same tree staged, the pkg-config file names the final prefix
make -s install PREFIX=/usr DESTDIR="$TMP/stage" >"$TMP/make" 2>&1
check destdir cond '[ -x "$TMP/stage/usr/bin/uasimpact" ] &&
  grep -qx "prefix=/usr" "$TMP/stage/usr/lib/pkgconfig/uasimpact.pc" &&
  grep -qx "libdir=/usr/lib" "$TMP/stage/usr/lib/pkgconfig/uasimpact.pc"'

# make run and make check build with one job per processor, unless -j was given
N=$(nproc 2>/dev/null || echo 2)
check run_parallel cond 'make -n run 2>/dev/null | grep -q -- "-j$N all\$" &&
  make -n check 2>/dev/null | grep -q -- "-j$N all mpi "'
check given_j_kept cond 'make -n -j3 run 2>/dev/null | grep -q "directory  *all\$"'
# the shared library is built before the tests run: test_install.sh and test_man.sh both run
# make install, two tests at a time, and on a fresh clone would otherwise both link it at once
check shlib_before_tests cond 'make -n check 2>/dev/null | grep -q -- " all mpi .* build/pic/libuasimpact.so.0.1\$" &&
  env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -nB check-san 2>/dev/null |
  grep -q -- "-j$N all build/pic/libuasimpact.so.0.1\$"'

# uninstall: nothing of ours is left (empty folders install made for others may stay)
make -s uninstall PREFIX="$P" >"$TMP/make" 2>&1
check uninstall_status [ $? -eq 0 ]
check uninstall_empty cond '[ -z "$(find "$P" -type f -o -type l)" ] || { find "$P" -type f -o -type l; false; }'
finish
