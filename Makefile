# uasimpact: drone-on-person impact risk workbench.
#   make          build ./uasimpact and build/libuasimpact.a
#   make run      set up, build, start the workbench (replays sessions/demo.ses without a terminal)
#   make check    set up, build, run every test
#   make bench    benchmarks (not part of check; tests/bench_scale.sh: 2 MPI ranks against 1);
#                 REPRODUCE=0 leaves out the timing of reproduce
#   make headdrop the 49 CFR 572.32 head drop on the person's scalp layer (a benchmark)
#   make reproduce  run sessions/paper.ses, report against the paper in build/reproduce/
#                   (STEP=0.2: a quick look on coarse grids, not a reproduction)
#   make calibrate  the declared fit of the model's unknowns to the training set (the paper's
#                 zero-wind grids; src/models/calibrate.spec, uasimpact-model(5)); build/calibration/
#                 (RESUME=build/calibration/log.csv: go on with a fit that was stopped)
#   make refit-drone, make refit-bag  the refit on materials in two stages (the drone on B and C,
#                 then the bag on A; uasimpact-model(5), CALIBRATION); build/refit-drone/, build/refit-bag/
#   make refit-verify  the refit's logged optimum (stage 2's best row, the final point) evaluated
#                 again, bit for bit (scripts/refit-verify.sh; minutes); build/refit-verify/
#   make membrane-convergence  the membrane airbag's mesh and time-step convergence on case A
#                 (scripts/membrane-convergence.sh; about a minute; make check runs it too:
#                 tests/test_membrane_convergence.sh and test_membrane_convergence_grid.sh)
#   make sensitivity  how far Table 17 moves with one unknown the calibration does not set
#                 moved in its public range, at the shipped models (scripts/sensitivity.sh;
#                 build/sensitivity/; STEP=0.2 for a quick look, VARIANTS=a,b for some only)
#   make check-san  every test again on an AddressSanitizer+UBSan build (build-san/), and a
#                 session under valgrind (scripts/check-san.sh)
#   make fuzz     libFuzzer targets tests/fuzz/fuzz_*.c (model language, scripts, part files),
#                 FUZZ_RUNS executions (FUZZ_RUN_RUNS for the executing script target) or
#                 FUZZ_SECONDS each (clang; build-fuzz/)
#   make mpi      ./uasimpact-mpi, the MPI build (OpenMPI from Debian; mpirun -n N ./uasimpact-mpi FILE)
#   make check-tsan  a ThreadSanitizer build (build-tsan/) runs a short grid on 2 threads and is
#                 interrupted by SIGINT in the middle (scripts/check-tsan.sh)
#   make format   apply the house style (.clang-format, clang-format 14) to every C source
#                 (scripts/format-files.sh); make check fails when a file would change
#   make install PREFIX=/usr/local [DESTDIR=staging] [LIBDIR=PREFIX/lib]: the programs
#                 (uasimpact-mpi when built), libuasimpact as a shared library with a soname and
#                 as an archive, its pkg-config file and headers, the man pages, and the sessions
#                 and example models under PREFIX/share/uasimpact (the program looks there after
#                 the current folder); make uninstall removes them

PREFIX  ?= /usr/local
CC      ?= cc
OPT     ?= -O3 -g
BUILD   ?= build
BIN     ?= uasimpact
# -fno-math-errno: sqrt inline and over vectors (the same IEEE results; errno is read only after
# strtod and file calls, never after a math function)
CFLAGS  += $(OPT) -fno-math-errno -std=c11 -D_POSIX_C_SOURCE=200809L -D_DEFAULT_SOURCE -Wall \
           -Wextra -Wshadow -Wno-unused-parameter -Wno-missing-field-initializers -Iinclude -MMD \
           -MP -pthread
LDFLAGS += -pthread

CORE_LIBS = -lgsl -lgslcblas -lm
# libxml2 (the report's HTML tree and serializer, src/app/report/report.c)
XML_CFLAGS := $(shell pkg-config --cflags libxml-2.0 2>/dev/null || echo -I/usr/include/libxml2)
XML_LIBS   := $(shell pkg-config --libs libxml-2.0 2>/dev/null || echo -lxml2)
# libjansson (JSON: set format json, the .meta.json beside an exported CSV; src/app/base/table.c)
JSON_LIBS  := $(shell pkg-config --libs jansson 2>/dev/null || echo -ljansson)
APP_LIBS  = -lreadline -lncursesw -ltinfo $(XML_LIBS) $(JSON_LIBS)
TEST_LIBS = -lcmocka

CORE_SRC  = $(sort $(wildcard src/core/*/*.c))
APP_SRC   = $(sort $(wildcard src/app/*/*.c src/app/*/*/*.c))
TEST_SRC  = $(sort $(wildcard tests/test_*.c tests/*/test_*.c tests/*/*/test_*.c))
BENCH_SRC = $(sort $(wildcard tests/bench_*.c))
MODELS    = $(sort $(wildcard src/models/*.urm))

CORE_OBJ  = $(CORE_SRC:%.c=$(BUILD)/%.o) $(if $(MODELS),$(BUILD)/models/builtin.o)
APP_OBJ   = $(APP_SRC:%.c=$(BUILD)/%.o)
TEST_BIN  = $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
BENCH_BIN = $(BENCH_SRC:tests/%.c=$(BUILD)/tests/%)

LIB     = $(BUILD)/libuasimpact.a
APPLIB  = $(BUILD)/libuasimpact-app.a

.PHONY: all deps run check test bench headdrop reproduce calibrate refit-drone refit-bag refit-verify sensitivity install uninstall \
  clean check-san fuzz \
  membrane-convergence \
  check-tsan mpi mpideps testdeps format
all: $(BIN) $(LIB)

# install missing Debian packages (quick no-op when all are there)
deps:
	@sh scripts/setup.sh

# the version, and the commit it was built from (uasimpact --version): git's in a checkout (-dirty
# with uncommitted changes), else the COMMIT file that git archive fills in (export-subst in
# .gitattributes); build/version.h is rewritten only when they change
VERSION = 0.1
ifeq ($(filter clean,$(MAKECMDGOALS)),)
COMMIT := $(shell [ "$$(git rev-parse --show-toplevel 2>/dev/null)" = "$(CURDIR)" ] && \
  git rev-parse --short=12 HEAD 2>/dev/null)
ifneq ($(COMMIT),)
COMMIT := $(COMMIT)$(shell git diff --quiet HEAD -- 2>/dev/null || echo -dirty)
else
COMMIT := $(shell sed -n '/^[0-9a-f][0-9a-f]*$$/p' COMMIT 2>/dev/null)
endif
$(shell mkdir -p $(BUILD) && printf '#define uraVERSION "%s"\n#define uraCOMMIT "%s"\n' \
  '$(VERSION)' '$(COMMIT)' | cmp -s - $(BUILD)/version.h || printf \
  '#define uraVERSION "%s"\n#define uraCOMMIT "%s"\n' '$(VERSION)' '$(COMMIT)' > $(BUILD)/version.h)
endif
$(BUILD)/src/app/base/version.o: $(BUILD)/version.h
$(BUILD)/src/app/base/version.o: CFLAGS += -I$(BUILD)
$(BUILD)/src/app/report/report.o: CFLAGS += $(XML_CFLAGS)

# everything is rebuilt when the compiler or its flags change (e.g. make OPT='-O0 -g')
FLAGS = $(BUILD)/.flags
ifeq ($(filter clean,$(MAKECMDGOALS)),)
$(shell mkdir -p $(BUILD) && echo '$(CC) $(CFLAGS) $(CORE_OPT)' | cmp -s - $(FLAGS) || \
  echo '$(CC) $(CFLAGS) $(CORE_OPT)' > $(FLAGS))
endif

$(BUILD)/%.o: %.c $(FLAGS) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -c $< -o $@

# built-in models: the .urm text files compiled in verbatim
$(BUILD)/models/builtin.c: $(MODELS) scripts/embed.sh
	@mkdir -p $(dir $@)
	sh scripts/embed.sh $(MODELS) > $@
$(BUILD)/models/builtin.o: $(BUILD)/models/builtin.c $(FLAGS)
	$(CC) $(CFLAGS) -c $< -o $@

$(LIB): $(CORE_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(APPLIB): $(APP_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(BIN): $(BUILD)/src/app/main.o $(APPLIB) $(LIB)
	$(CC) $(LDFLAGS) -o $@ $^ $(APP_LIBS) $(CORE_LIBS)

$(BUILD)/tests/%: tests/%.c $(APPLIB) $(LIB) $(FLAGS) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< $(APPLIB) $(LIB) $(LDFLAGS) $(TEST_LIBS) $(APP_LIBS) $(CORE_LIBS)

# bench_step times the stages of a step alone by the step's own stage timer: engine_run.c built
# with urSTEP_PROF, linked before the library (whose engine_run.o, without the timer, is then not
# linked); the library itself has no timer
STEP_PROF_OBJ = $(BUILD)/tests/engine_run_prof.o
$(STEP_PROF_OBJ): src/core/engine/engine_run.c $(FLAGS) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -DurSTEP_PROF -c $< -o $@
$(BUILD)/tests/bench_step: tests/bench_step.c $(STEP_PROF_OBJ) $(APPLIB) $(LIB) $(FLAGS) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -o $@ $< $(STEP_PROF_OBJ) $(APPLIB) $(LIB) $(LDFLAGS) $(TEST_LIBS) $(APP_LIBS) \
	  $(CORE_LIBS)

# the MPI build: only the distributor (src/app/scale/scale_mpi.c) is compiled by mpicc with URA_MPI;
# its object comes before the application's archive, whose MPI-less stub is then not linked
MPICC ?= mpicc
MPI_BIN = uasimpact-mpi
mpideps:
	@sh scripts/setup.sh mpi
mpi: $(MPI_BIN)
$(BUILD)/mpi/scale_mpi.o: src/app/scale/scale_mpi.c $(FLAGS) | mpideps
	@mkdir -p $(dir $@)
	$(MPICC) $(CFLAGS) -DURA_MPI -c $< -o $@
$(MPI_BIN): $(BUILD)/src/app/main.o $(BUILD)/mpi/scale_mpi.o $(APPLIB) $(LIB) | mpideps
	$(MPICC) $(LDFLAGS) -o $@ $^ $(APP_LIBS) $(CORE_LIBS)

# make run and make check build with one job per processor unless -j was given
NPROC := $(shell nproc 2>/dev/null || echo 2)
JOBS = $(if $(findstring -j,$(MAKEFLAGS)),,-j$(NPROC))
run:
	@$(MAKE) --no-print-directory $(JOBS) all
	@if [ -t 0 ]; then ./uasimpact; else ./uasimpact sessions/demo.ses; fi

# what the tests need beyond the build (scripts/setup.sh test: python3-pandas)
testdeps:
	@sh scripts/setup.sh test
# the shared library too: test_install.sh and test_man.sh run make install two at a time, and on
# a fresh clone each would otherwise link it into the same file at once
check: testdeps
	@$(MAKE) --no-print-directory $(JOBS) all mpi $(TEST_BIN) $(BUILD)/calibrate $(SHLIB)
	@TEST_TIMES=$(BUILD)/test-times sh scripts/runtests.sh $(TEST_BIN)

test: check

REPRODUCE ?= 1
bench: all mpi $(BENCH_BIN)
	@for b in $(BENCH_BIN); do $$b || exit 1; done
	@sh tests/bench_scale.sh
	@if [ "$(REPRODUCE)" != 0 ]; then t0=$$(date +%s); \
	  echo "bench: timing make reproduce (many minutes; progress in $(BUILD)/reproduce.log)"; \
	  sh scripts/reproduce.sh >$(BUILD)/reproduce.log 2>&1 || { cat $(BUILD)/reproduce.log; exit 1; }; \
	  echo "bench: make reproduce: $$(($$(date +%s) - t0)) s wall (issue 36: target 60 s; report in $(BUILD)/reproduce/report.md)"; \
	else echo "bench: make reproduce not timed (REPRODUCE=0)"; fi

# the head drop of 49 CFR 572.32 on the person's scalp layer (issue 33; a benchmark)
headdrop: $(BUILD)/tests/bench_headdrop
	@$<

# the membrane airbag's convergence (issue 32): mesh N -> 2N, dt halved, at case A's centre and
# over its zero-wind grid (STEP, default 0.05)
membrane-convergence: all
	@sh scripts/membrane-convergence.sh $(STEP)

# the paper's results side by side with ours (scripts/reproduce.sh); minutes of grids
reproduce: all
	@sh scripts/reproduce.sh $(if $(STEP),-s $(STEP) -o $(BUILD)/reproduce-step$(STEP))

# the declared calibration (src/tools/calibrate.c): every evaluation in build/calibration/log.csv,
# the best values in build/calibration/result.txt; CALIBRATE_ARGS for more (e.g. -n 50);
# RESUME=LOG replays LOG's evaluations (calibrate -r) and goes on
$(BUILD)/calibrate: src/tools/calibrate.c $(APPLIB) $(LIB) $(FLAGS) | deps
	$(CC) $(CFLAGS) -o $@ $< $(APPLIB) $(LIB) $(LDFLAGS) $(APP_LIBS) $(CORE_LIBS)
# a resumed fit replays its log under the defaults it ran with (src/models/replay.pins)
PINS = $(shell sh scripts/replay-pins.sh)
calibrate: all $(BUILD)/calibrate
	$(BUILD)/calibrate -o $(BUILD)/calibration $(if $(RESUME),-r $(RESUME) $(PINS)) $(CALIBRATE_ARGS)

# the refit on materials (uasimpact-model(5), CALIBRATION): stage 1, the drone on cases B and C;
# stage 2, the bag on case A (its spec written from stage 1's result by scripts/refit.sh and
# committed before it runs); hours at the membrane's mesh 14. RESUME=LOG resumes either.
refit-drone: all $(BUILD)/calibrate
	$(BUILD)/calibrate -s src/models/refit-drone.spec -o $(BUILD)/refit-drone \
	  $(if $(RESUME),-r $(RESUME) $(PINS)) $(CALIBRATE_ARGS)
refit-bag: all $(BUILD)/calibrate
	@test -r src/models/refit-bag.spec || { echo "make refit-bag: src/models/refit-bag.spec is \
	written from stage 1's result: sh scripts/refit.sh bag RESULT > src/models/refit-bag.spec"; \
	exit 1; }
	$(BUILD)/calibrate -s src/models/refit-bag.spec -o $(BUILD)/refit-bag \
	  $(if $(RESUME),-r $(RESUME) $(PINS)) $(CALIBRATE_ARGS)
# the refit's logged optimum evaluated again on this build, bit for bit (scripts/refit-verify.sh;
# stage 2's best row and the final point: about ten minutes)
refit-verify: all $(BUILD)/calibrate
	@sh scripts/refit-verify.sh $(BUILD)/refit-verify

# how far the public ranges of the unknowns move Table 17 (scripts/sensitivity.sh); minutes
sensitivity: all
	@sh scripts/sensitivity.sh $(if $(STEP),-s $(STEP) -o $(BUILD)/sensitivity-step$(STEP)) \
	  $(if $(VARIANTS),-v $(VARIANTS))

# the same tests on a sanitized build of its own (build-san/uasimpact and build-san/calibrate are
# what the shell tests run; the plain build and shared library are built first only because
# test_install.sh and test_man.sh run make install two at a time); its lanes are the portable
# vector code without the AVX2 clones (urNO_CLONES), so that the lanes-equal-alone tests cover
# both code paths (make check runs the AVX2 clone where the processor has AVX2). The valgrind
# session runs a plain build of the same portable path (build-vg/uasimpact): valgrind 3.19 cannot
# decode every AVX instruction GCC emits in the clones.
SAN_OPT = -O2 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer \
  -DurNO_CLONES
check-san:
	@sh scripts/setup.sh san
	@$(MAKE) --no-print-directory BUILD=build-san BIN=build-san/uasimpact OPT='$(SAN_OPT)' \
	  LDFLAGS='-pthread $(SAN_OPT)' build-san/uasimpact build-san/calibrate \
	  $(TEST_SRC:tests/%.c=build-san/tests/%)
	@$(MAKE) --no-print-directory BUILD=build-vg BIN=build-vg/uasimpact OPT='-O2 -g -DurNO_CLONES' \
	  build-vg/uasimpact
	@$(MAKE) --no-print-directory $(JOBS) all $(SHLIB)
	@sh scripts/check-san.sh build-san build-vg/uasimpact

# fuzzing with libFuzzer: each target until FUZZ_RUNS executions or FUZZ_SECONDS, corpora in
# tests/fuzz/corpus_*. Each target has its own build: the model-language target instruments
# everything for coverage; the command targets only the application (the core, the model parser
# above all, is the model target's field and would slow them five-fold), under ASan+UBSan all.
# The part file target (fuzz_part: the reader merge trusts) shares the command targets' build.
# The executing script target (fuzz_run: short simulations, files in a scratch folder, a fake
# gnuplot) is slower per input: FUZZ_RUN_RUNS executions.
FUZZ_SAN = -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_OPT = $(FUZZ_SAN) -fsanitize=fuzzer-no-link
FUZZ_RUNS ?= 1000000
FUZZ_RUN_RUNS ?= 100000
FUZZ_SECONDS ?= 7200
fuzz:
	@sh scripts/setup.sh fuzz
	@$(MAKE) --no-print-directory BUILD=build-fuzz/model CC=clang OPT='$(FUZZ_OPT)' \
	  build-fuzz/model/fuzz/fuzz_model
	@$(MAKE) --no-print-directory BUILD=build-fuzz/script CC=clang OPT='$(FUZZ_OPT)' \
	  CORE_OPT='$(FUZZ_SAN)' build-fuzz/script/fuzz/fuzz_script build-fuzz/script/fuzz/fuzz_run \
	  build-fuzz/script/fuzz/fuzz_part
	@sh scripts/fuzz.sh $(FUZZ_RUNS) $(FUZZ_SECONDS) build-fuzz/model/fuzz/fuzz_model \
	  build-fuzz/script/fuzz/fuzz_script build-fuzz/script/fuzz/fuzz_part
	@sh scripts/fuzz.sh $(FUZZ_RUN_RUNS) $(FUZZ_SECONDS) build-fuzz/script/fuzz/fuzz_run

# ThreadSanitizer: the application and the core built with -fsanitize=thread (build-tsan/), a
# short grid on 2 threads interrupted by SIGINT while its workers run; any report fails
TSAN_OPT = -O1 -g -fsanitize=thread -fno-omit-frame-pointer -DurNO_CLONES
check-tsan:
	@sh scripts/setup.sh tsan
	@$(MAKE) --no-print-directory BUILD=build-tsan BIN=build-tsan/uasimpact OPT='$(TSAN_OPT)' \
	  LDFLAGS='-pthread $(TSAN_OPT)' build-tsan/uasimpact
	@sh scripts/check-tsan.sh build-tsan/uasimpact

# the core built with other options than the application (CORE_OPT, for the fuzz builds)
ifneq ($(CORE_OPT),)
$(BUILD)/src/core/%.o $(BUILD)/models/builtin.o: override OPT := $(CORE_OPT)
endif

$(BUILD)/fuzz/%: tests/fuzz/%.c $(APPLIB) $(LIB) $(FLAGS) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -fsanitize=fuzzer -o $@ $< $(APPLIB) $(LIB) $(LDFLAGS) $(APP_LIBS) $(CORE_LIBS)

# the shared library: the core again as position-independent code (built for install only, so
# that make and make run compile the core once); the soname carries the major version
SO_MAJOR = 0
SONAME   = libuasimpact.so.$(SO_MAJOR)
SHLIB    = $(BUILD)/pic/libuasimpact.so.$(VERSION)
PIC_OBJ  = $(CORE_SRC:%.c=$(BUILD)/pic/%.o) $(if $(MODELS),$(BUILD)/pic/models/builtin.o)
$(BUILD)/pic/src/%.o: src/%.c $(FLAGS) | deps
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -fPIC -c $< -o $@
$(BUILD)/pic/models/builtin.o: $(BUILD)/models/builtin.c $(FLAGS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) -fPIC -c $< -o $@
$(SHLIB): $(PIC_OBJ)
	$(CC) -shared -Wl,-soname,$(SONAME) $(LDFLAGS) -o $@ $^ $(CORE_LIBS)

# where install puts things (Debian's layout under PREFIX; LIBDIR may be PREFIX/lib/TRIPLET)
LIBDIR  ?= $(PREFIX)/lib
DATADIR  = $(PREFIX)/share/uasimpact
MANDIR   = $(PREFIX)/share/man
D        = $(DESTDIR)
# the data: every session and what they load (the example quadcopter, the paper's grids)
DATA     = $(shell find sessions -type f 2>/dev/null | LC_ALL=C sort)

install: all $(SHLIB)
	install -d $(D)$(PREFIX)/bin $(D)$(LIBDIR)/pkgconfig $(D)$(PREFIX)/include/uasimpact \
	  $(D)$(MANDIR)/man1 $(D)$(MANDIR)/man5 $(D)$(MANDIR)/man7 $(D)$(DATADIR)
	install -m 755 uasimpact $(D)$(PREFIX)/bin/
	if [ -x $(MPI_BIN) ]; then install -m 755 $(MPI_BIN) $(D)$(PREFIX)/bin/; fi
	install -m 644 $(LIB) $(D)$(LIBDIR)/
	install -m 644 $(SHLIB) $(D)$(LIBDIR)/
	ln -sf libuasimpact.so.$(VERSION) $(D)$(LIBDIR)/$(SONAME)
	ln -sf $(SONAME) $(D)$(LIBDIR)/libuasimpact.so
	printf 'prefix=%s\nlibdir=%s\nincludedir=%s\n\nName: uasimpact\nDescription: %s\nVersion: %s\nLibs: -L$${libdir} -luasimpact\nLibs.private: %s\nCflags: -I$${includedir}\n' \
	  '$(PREFIX)' '$(LIBDIR)' '$(PREFIX)/include' \
	  'drone-on-person impact simulation and risk (Q = A_impact P{F|impact})' '$(VERSION)' \
	  '$(CORE_LIBS)' >$(D)$(LIBDIR)/pkgconfig/uasimpact.pc
	install -m 644 include/uasimpact/*.h $(D)$(PREFIX)/include/uasimpact/
	install -m 644 man/*.1 $(D)$(MANDIR)/man1/
	for f in man/*.5; do [ -e "$$f" ] && install -m 644 "$$f" $(D)$(MANDIR)/man5/; done; true
	for f in man/*.7; do [ -e "$$f" ] && install -m 644 "$$f" $(D)$(MANDIR)/man7/; done; true
	for f in $(DATA); do install -D -m 644 "$$f" "$(D)$(DATADIR)/$$f" || exit 1; done

# what install put there, and the folders it made that are then empty
uninstall:
	rm -f $(D)$(PREFIX)/bin/uasimpact $(D)$(PREFIX)/bin/$(MPI_BIN) \
	  $(D)$(LIBDIR)/libuasimpact.a $(D)$(LIBDIR)/libuasimpact.so.$(VERSION) \
	  $(D)$(LIBDIR)/$(SONAME) $(D)$(LIBDIR)/libuasimpact.so $(D)$(LIBDIR)/pkgconfig/uasimpact.pc
	rm -rf $(D)$(PREFIX)/include/uasimpact $(D)$(DATADIR)
	for f in man/*.[157]; do rm -f "$(D)$(MANDIR)/man$${f##*.}/$${f##*/}"; done
	-rmdir $(D)$(LIBDIR)/pkgconfig 2>/dev/null; true

# the house style on every source; the transitional list of sources not yet formatted goes
CLANG_FORMAT ?= clang-format
format:
	$(CLANG_FORMAT) -i $$(sh scripts/format-files.sh)
	rm -f .clang-format-pending

clean:
	rm -rf $(BUILD) build-san build-vg build-fuzz build-tsan uasimpact uasimpact-mpi

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
