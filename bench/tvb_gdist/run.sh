#!/usr/bin/env bash
# Copyright (c) 2026 The CGAL_ext geodesics developers.
#
# Compiles local_rows_driver.cpp against a tvb-gdist source folder (not part of this project:
# bring your own checkout) with the flags of our benchmarks, and runs it.
#
# Usage: run.sh TVB_GDIST_SOURCE_DIR MESH [K=200] [R=10] [DUMP_PREFIX]
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: $0 TVB_GDIST_SOURCE_DIR MESH [K=200] [R=10] [DUMP_PREFIX]" >&2
  exit 2
fi
src=$1; mesh=$2; k=${3:-200}; r=${4:-10}
here=$(cd "$(dirname "$0")" && pwd)
# the headers live in geodesic_library/ in a tvb-gdist checkout; accept that folder itself too
inc=$src/geodesic_library
[ -f "$inc/geodesic_algorithm_exact.h" ] || inc=$src
if [ ! -f "$inc/geodesic_algorithm_exact.h" ]; then
  echo "$0: no geodesic_algorithm_exact.h in $src or $src/geodesic_library" >&2
  exit 1
fi
exe=$(mktemp /tmp/tvb_gdist_local_rows_driver.XXXXXX)
trap 'rm -f "$exe"' EXIT
# -w: tvb-gdist's headers are old code and warn a lot; the flags that matter are ours
g++ -std=c++17 -O3 -DNDEBUG -w -I"$inc" "$here/local_rows_driver.cpp" -o "$exe"
"$exe" "$mesh" "$k" "$r" ${5:+"$5"}
