#!/bin/sh
# format-files.sh: the C sources the house style (.clang-format) covers, one per line: what
# 'make format' rewrites and tests/test_format.sh checks: every .c and .h under src, include and
# tests, in every folder. Generated files (build/) are not sources.
find src include tests \( -name '*.c' -o -name '*.h' \) -type f 2>/dev/null | LC_ALL=C sort
