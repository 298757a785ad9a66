#!/usr/bin/env bash
# Packs the release binaries with the shared libraries they link against
# into one archive, to measure them on another x86-64 Linux machine that
# has a GPU driver but none of eikon's packages (docs/benchmarks-gpu.md,
# "Measuring on a GPU machine"). The C and C++ runtimes and the OpenGL/EGL
# libraries stay out: the machine's own are newer, and its GPU vendor's
# libGL/libEGL must be the ones loaded.
#   tools/bundle-release.sh [BUILD_DIR] [ARCHIVE]
# The archive unpacks to bin/ and lib/; run with LD_LIBRARY_PATH=DIR/lib.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
archive=${2:-build/gpu-kit/eikon-release.tar.xz}
binaries=(eikon bench_fluid_step bench_lattice bench_export bench_mesh_voxelize)

stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/bin" "$stage/lib"
for binary in "${binaries[@]}"; do cp "$build/$binary" "$stage/bin/"; done

# Left to the machine: the loader and C/C++ runtimes, and the GL vendor stack.
system_library='^(linux-vdso|ld-linux|libc\.|libm\.|libdl\.|libpthread\.|librt\.|libgcc_s\.|libstdc\+\+\.|libGL|libEGL|libOpenGL|libGLX|libGLdispatch|libgbm\.|libdrm)'
for binary in "${binaries[@]}"; do
    ldd "$build/$binary" | awk '$2 == "=>" && $3 ~ /^\// { print $3 }'
done | sort -u | while read -r library; do
    name=$(basename "$library")
    [[ $name =~ $system_library ]] || cp -L "$library" "$stage/lib/$name"
done

mkdir -p "$(dirname "$archive")"
tar -C "$stage" -cf - bin lib | xz -T0 -6 > "$archive.tmp"
mv "$archive.tmp" "$archive"
echo "$archive: $(du -h "$archive" | cut -f1), $(ls "$stage/lib" | wc -l) libraries"
