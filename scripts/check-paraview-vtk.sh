#!/usr/bin/env bash
# Compile check: every Plume module source (Modules/*/*.cxx) must compile
# against ParaView 5.11's bundled VTK 9.2 headers, not only Debian's VTK 9.1.
#
# ParaView cannot be installed next to the project's VTK 9.1 (python3-paraview
# conflicts with python3-vtk9, which libvtk9-dev needs), so the headers come
# from the paraview-dev .deb, downloaded with `apt-get download` and unpacked
# into a private cache: the machine's installed packages are not touched.
# Besides libc/libstdc++, the only outside header ParaView's VTK headers pull
# in for our sources is <GL/glew.h>: Debian's libglew-dev, which libvtk9-dev
# already installs (ParaView links the same GLEW 2.2).
#
# Each source gets `g++ -std=c++17 -fsyntax-only` with ParaView's include dir
# plus Plume's own source and generated headers (export headers, encoded
# shaders) from the build dir. A file fails if it does not compile, if it
# uses anything deprecated in 9.2 (removed in the next VTK), or if any VTK
# header it includes comes from anywhere but ParaView's include dir.
# Not covered: linking or running against 9.2, tests, the command line.
#
# Usage: PLUME_BUILD_DIR=build bash scripts/check-paraview-vtk.sh
#   PLUME_BUILD_DIR  a configured and built Plume build dir (default: build)
#   PLUME_CHECK_JOBS parallel compiles (default: nproc)
#   PLUME_COMPAT_PLUGIN_BUILDS=1  the ParaView plugin will be built in the same
#                    run (scripts/test.sh sets it unless PLUME_SKIP_PARAVIEW=1):
#                    its build compiles the modules it lists in
#                    ParaView/Plugin/CMakeLists.txt against the same 9.2 headers,
#                    with -Werror=deprecated-declarations and no VTK 9.1 in its
#                    root, so only the other modules' sources are checked here.
# Cache: $PLUME_BUILD_DIR/paraview-vtk92 (reused; delete it to refetch).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${PLUME_BUILD_DIR:-$root/build}"
if [ ! -d "$build/Modules" ]; then
  echo "check-paraview-vtk: '$build' is not a built Plume build dir (set PLUME_BUILD_DIR)" >&2
  exit 2
fi
build="$(cd "$build" && pwd)"
cache="$build/paraview-vtk92"
jobs="${PLUME_CHECK_JOBS:-$(nproc)}"
cxx="${PLUME_CHECK_CXX:-g++}"

# --- ParaView's headers, fetched once ----------------------------------------
if [ ! -d "$cache/include" ]; then
  rm -rf "$cache/debs" "$cache/include.tmp"
  mkdir -p "$cache/debs" "$cache/include.tmp"
  apt_opts=(-q)
  # As root, apt's _apt sandbox user cannot write into the cache dir.
  if [ "$(id -u)" -eq 0 ]; then apt_opts+=(-o APT::Sandbox::User=root); fi
  if ! (cd "$cache/debs" && apt-get "${apt_opts[@]}" download paraview-dev); then
    # Package lists missing or stale (a fresh machine): refresh them, retry.
    # apt-get update changes no installed package.
    if [ "$(id -u)" -eq 0 ]; then apt-get update -q; else sudo apt-get update -q; fi
    (cd "$cache/debs" && apt-get "${apt_opts[@]}" download paraview-dev)
  fi
  deb="$(ls "$cache"/debs/paraview-dev_*.deb)"
  dpkg-deb --fsys-tarfile "$deb" | tar -x -C "$cache/include.tmp" --wildcards './usr/include/*'
  mv "$cache/include.tmp" "$cache/include"
  rm -rf "$cache/debs"
fi
pvinc="$(find "$cache/include/usr/include" -maxdepth 1 -type d -name 'paraview-5.11' | head -n 1)"
if [ -z "$pvinc" ] || [ ! -f "$pvinc/vtkVersionMacros.h" ]; then
  echo "check-paraview-vtk: no ParaView 5.11 VTK headers under $cache/include (delete it to refetch)" >&2
  exit 2
fi
if [ ! -f /usr/include/GL/glew.h ]; then
  echo "check-paraview-vtk: /usr/include/GL/glew.h missing (libglew-dev; scripts/install-deps.sh installs it)" >&2
  exit 2
fi

# --- Flags: ParaView's VTK, Plume's sources and generated headers ------------
flags=(-std=c++17 -fsyntax-only -Wall -Wextra -Werror=deprecated-declarations -isystem "$pvinc")
for dir in "$root"/Modules/*/; do
  name="$(basename "$dir")"
  flags+=(-I "$build/Modules/$name" -I "$root/Modules/$name")
done

# Plume::Solver also includes hypre's headers, which include MPI's (Debian's
# libhypre-dev and its Open MPI; ParaView's VTK is MPI-enabled against the same).
if [ -f /usr/include/hypre/HYPRE_struct_ls.h ]; then
  flags+=(-isystem /usr/include/hypre)
  for dir in $(pkg-config --cflags-only-I ompi-c 2>/dev/null | sed 's/-I//g'); do flags+=(-isystem "$dir"); done
fi

# The headers really are 9.2: a probe that fails on any other version.
probe="$(printf '%s\n' '#include <vtkVersionMacros.h>' \
  '#if !(VTK_MAJOR_VERSION == 9 && VTK_MINOR_VERSION == 2)' \
  '#error "expected VTK 9.2 headers"' '#endif' \
  'const char* plumeVersion = VTK_VERSION;')"
if ! echo "$probe" | "$cxx" "${flags[@]}" -x c++ -; then
  echo "check-paraview-vtk: the headers in $pvinc are not VTK 9.2" >&2
  exit 1
fi
vtk_version="$(sed -n 's/^#define VTK_VERSION "\(.*\)"/\1/p' "$pvinc/vtkVersionMacros.h")"

# --- One compile per module source, in parallel -------------------------------
logs="$cache/logs"
rm -rf "$logs"
mkdir -p "$logs"
check_one() {
  local src="$1" rel name log start status
  rel="${src#"$root"/}"
  name="$(basename "$(dirname "$src")")"
  log="$logs/$(echo "$rel" | tr '/' '_').log"
  start=$(date +%s%N)
  status=ok
  # -H lists every header opened (lines starting with dots): kept to check
  # where the VTK ones came from.
  if ! "$cxx" "${flags[@]}" "-D${name}_EXPORTS" -H "$src" >"$log" 2>&1; then
    status=FAIL
  else
    # Every vtk* header (or vtk* directory) must come from ParaView's include
    # dir or from Plume's own source/build dirs: never Debian's vtk-9.1.
    local leaked
    leaked="$(grep -E '^\.+ ' "$log" | sed -E 's/^\.+ //' | grep -E '/vtk[^/]*(/|$)' |
      grep -v -e "^$pvinc/" -e "^$root/Modules/" -e "^$build/Modules/" -e "^Modules/" | sort -u || true)"
    if [ -n "$leaked" ]; then
      status=FAIL
      { echo "VTK headers from outside $pvinc:"; echo "$leaked" | sed 's/^/  /'; } >>"$log"
    fi
  fi
  local warnings
  warnings=$(grep -c 'warning:' "$log" || true)
  local ms=$((($(date +%s%N) - start) / 1000000))
  printf '%s\t%s\t%d.%d\t%s\t%s\n' "$status" "$rel" $((ms / 1000)) $((ms % 1000 / 100)) "$warnings" "$log" \
    >"$log.result"
}
export -f check_one
export root build pvinc logs cxx
# Arrays cannot be exported: hand the flags over NUL-separated.
printf '%s\0' "${flags[@]}" >"$logs/flags"
start_all=$(date +%s)
skip_modules=()
if [ "${PLUME_COMPAT_PLUGIN_BUILDS:-0}" = 1 ]; then
  mapfile -t skip_modules < <(sed -n 's|.*{plume_modules_dir}/\([A-Za-z]*\)/vtk.module.*|\1|p' \
    "$root/ParaView/Plugin/CMakeLists.txt")
  if [ ${#skip_modules[@]} -eq 0 ]; then
    echo "check-paraview-vtk: no module list found in ParaView/Plugin/CMakeLists.txt" >&2
    exit 1
  fi
  echo "check-paraview-vtk: left to the ParaView plugin's build: ${skip_modules[*]}"
fi
sources() {
  local src name skip
  while IFS= read -r -d '' src; do
    name="$(basename "$(dirname "$src")")"
    for skip in "${skip_modules[@]}"; do
      if [ "$name" = "$skip" ]; then continue 2; fi
    done
    printf '%s\0' "$src"
  done < <(find "$root"/Modules -mindepth 2 -maxdepth 2 -name '*.cxx' -print0 | sort -z)
}
sources | xargs -0 -r -n 1 -P "$jobs" bash -c 'mapfile -d "" -t flags <"$logs/flags"; check_one "$1"' _
elapsed=$(($(date +%s) - start_all))

# --- Report --------------------------------------------------------------------
passed=0
failed=0
echo "check-paraview-vtk: ParaView 5.11 VTK $vtk_version headers ($pvinc)"
while IFS=$'\t' read -r status rel secs warnings log; do
  note=""
  if [ "$warnings" -gt 0 ]; then note=" ($warnings warnings, see $log)"; fi
  printf '%-4s %s  %ss%s\n' "$status" "$rel" "$secs" "$note"
  if [ "$status" = ok ]; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    grep -v -E '^\.+ |^Multiple include guards|^/[^:]*$' "$log" | head -n 20 | sed 's/^/     | /'
  fi
done < <(cat "$logs"/*.result | sort -k2)
total=$((passed + failed))
if [ "$total" -eq 0 ]; then
  echo "check-paraview-vtk: no module sources found under $root/Modules" >&2
  exit 1
fi
echo "check-paraview-vtk: $passed of $total module sources compile against VTK $vtk_version ($failed failing, ${elapsed}s)"
[ "$failed" -eq 0 ]
