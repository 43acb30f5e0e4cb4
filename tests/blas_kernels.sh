#!/bin/sh
# build/ndda started without OPENBLAS_CORETYPE on a CPU with AVX2 and FMA
# starts itself again with OpenBLAS's Haswell kernels (source/main.cc), as
# ndda.sh and the suite set them: the BLAS line names them, and the
# measure points are byte for byte those of a run with the variable set.
# Skipped (77) on a CPU without AVX2 and FMA, or without OpenBLAS.
# Usage: blas_kernels.sh <ndda> <scene.prm> <work directory>
set -e
ndda="$1"
scene="$2"
work="$3"
grep -qw avx2 /proc/cpuinfo && grep -qw fma /proc/cpuinfo || exit 77
rm -rf "$work"
mkdir -p "$work/unset" "$work/set"
(cd "$work/unset" && env -u OPENBLAS_CORETYPE "$ndda" --threads 1 "$scene" > screen-output 2>&1)
(cd "$work/set" && OPENBLAS_CORETYPE=Haswell "$ndda" --threads 1 "$scene" > screen-output 2>&1)
blas=$(grep "BLAS:" "$work/unset/screen-output")
case "$blas" in
  *OpenBLAS*) ;;
  *) echo "not OpenBLAS: $blas"; exit 77 ;;
esac
case "$blas" in
  *Haswell*) echo "started without OPENBLAS_CORETYPE: Haswell kernels" ;;
  *) echo "started without OPENBLAS_CORETYPE: $blas"; exit 1 ;;
esac
unset_points=$(find "$work/unset" -name measure_points.txt)
set_points=$(find "$work/set" -name measure_points.txt)
[ -n "$unset_points" ] && [ -n "$set_points" ] || { echo "no measure points"; exit 1; }
cmp "$unset_points" "$set_points"
echo "measure points the same as with OPENBLAS_CORETYPE=Haswell"
