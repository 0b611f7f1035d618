#!/bin/sh
# format-files.sh: the C sources the house style (.clang-format) covers, one per line: what
# 'make format' rewrites and tests/test_format.sh checks. Generated files (build/) are not sources.
ls src/core/*.c src/core/*.h src/app/*.c src/app/*.h src/tools/*.c include/uasimpact/*.h \
  tests/*.c tests/*.h tests/fuzz/*.c 2>/dev/null
