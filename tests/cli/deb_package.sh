#!/usr/bin/env bash
# The Debian package (cmake/GfecPackage.cmake): `cpack -G DEB` from the build tree into a
# scratch folder gives gfec_<version>_amd64.deb; dpkg-deb -c lists the compiler, the runtime, the
# man page, the completion where bash-completion looks and the CMake package; dpkg-deb -x into a
# scratch root (never the real system), and the extracted gfec compiles a sample chart, runs its
# scenario tests, and a CMake project finds the package there with CMAKE_PREFIX_PATH.
# Usage: deb_package.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build_dir=$(cd "$1" && pwd) source_dir=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# dpkg-deb is in dpkg, on every Debian machine; dpkg-shlibdeps (dpkg-dev) makes the Depends line.
for tool in cpack dpkg-deb dpkg-shlibdeps; do
  if ! command -v "$tool" >/dev/null; then
    [ "${CI:-}" = true ] && fail "$tool is not installed (scripts/install-deps.sh)"
    echo "SKIP: no $tool (Debian packages cmake, dpkg, dpkg-dev)"
    exit 0
  fi
done

version=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build_dir/CMakeCache.txt")
[ -n "$version" ] || fail "no project version in $build_dir/CMakeCache.txt"
cpack -G DEB --config "$build_dir/CPackConfig.cmake" -B "$work/out" >"$work/cpack.log" 2>&1 ||
  fail "cpack: $(cat "$work/cpack.log")"
deb="$work/out/gfec_${version}_$(dpkg --print-architecture).deb"
[ -f "$deb" ] || fail "no $(basename "$deb"): $(ls "$work/out")"

fields=$(dpkg-deb -f "$deb" Package Version Maintainer Depends Description)
for field in "Package: gfec" "Version: $version" "Maintainer: " "Description: "; do
  grep -q "^$field" <<<"$fields" || fail "the control file has no '$field': $fields"
done
# dpkg-shlibdeps named the libraries gfec is linked with.
depends=$(dpkg-deb -f "$deb" Depends)
for lib in libc6 libstdc++6; do grep -q "$lib" <<<"$depends" || fail "Depends lacks $lib: $depends"; done
if ldd "$build_dir/gfec" | grep -q libfmt; then
  grep -q libfmt <<<"$depends" || fail "gfec links libfmt, Depends does not name it: $depends"
fi

listing=$(dpkg-deb -c "$deb" | awk '{ print $6 }')
for path in ./usr/bin/gfec ./usr/share/man/man1/gfec.1 ./usr/share/bash-completion/completions/gfec \
            ./usr/share/doc/gfec/tutorial.md ./usr/include/afp/afp.h \
            ./usr/lib/cmake/gfec/gfecConfig.cmake ./usr/lib/cmake/gfec/gfecConfigVersion.cmake \
            ./usr/lib/cmake/gfec/gfecTargets.cmake ./usr/lib/cmake/gfec/gfecRuntimeTargets.cmake \
            ./usr/lib/cmake/gfec/GfecChart.cmake; do
  grep -qxF "$path" <<<"$listing" || fail "the package holds no $path"
done
grep -q '^\./usr/lib/.*libafp_runtime\.a$' <<<"$listing" || fail "the package holds no runtime library"
# Nothing outside /usr, nothing of the build or source tree.
bad=$(grep -v -e '^\./$' -e '^\./usr/' <<<"$listing" || true)
[ -z "$bad" ] || fail "the package holds files outside /usr: $bad"

root="$work/root"
dpkg-deb -x "$deb" "$root"
gfec="$root/usr/bin/gfec"
[ -x "$gfec" ] || fail "no executable usr/bin/gfec in the extracted package"
"$gfec" --version | grep -q "$version" || fail "gfec --version: $("$gfec" --version)"
# The extracted gfec finds the extracted guides (the path bin/../share/doc/gfec).
"$gfec" --help | grep -qxF "Documentation: man gfec; $root/usr/share/doc/gfec/cli.md" ||
  fail "gfec --help does not cite the packaged guide: $("$gfec" --help | tail -1)"

# bash-completion finds the completion where the package puts it (root/usr/share stands for /usr/share).
loader=/usr/share/bash-completion/bash_completion
if [ -f "$loader" ]; then
  loaded=$(XDG_DATA_DIRS="$root/usr/share" BASH_COMPLETION_USER_DIR="$work/none" bash -c \
    'source "$1"; __load_completion gfec && complete -p gfec' _ "$loader" 2>&1) ||
    fail "bash-completion did not load the packaged completion: $loaded"
elif [ "${CI:-}" = true ]; then
  fail "bash-completion is not installed (Debian package bash-completion)"
fi

# A sample chart, compiled into a C engine that compiles; its scenario tests pass.
cp "$source_dir"/samples/line_follower.sfc "$source_dir"/samples/linebot.iface \
   "$source_dir"/samples/line_follower.test "$work/"
mkdir "$work/engine"
(cd "$work" && "$gfec" -Werror -o engine/line_follower.c line_follower.sfc) 2>"$work/gfec.err" ||
  fail "compiling line_follower.sfc: $(cat "$work/gfec.err")"
cc -std=c99 -Wall -Werror -c "$work/engine/line_follower.c" -o "$work/engine.o" || fail "the engine does not compile"
tested=$(cd "$work" && "$gfec" test line_follower.test 2>&1) || fail "gfec test: $tested"
grep -Eq "^[1-9][0-9]* passed, 0 failed" <<<"$tested" || fail "gfec test printed: $tested"

# The CMake package is relocatable: a project finds it under the scratch root.
if command -v ninja >/dev/null; then generator=Ninja; else generator="Unix Makefiles"; fi
project="$work/project"
cp -r "$source_dir/tests/cli/package_project" "$project"
# A sanitizer build of gfec packages a sanitized runtime: link the project the same way.
flags=()
if [ -n "${GFEC_SANITIZE:-}" ]; then
  flags=(-DCMAKE_C_FLAGS="-fsanitize=$GFEC_SANITIZE" -DCMAKE_CXX_FLAGS="-fsanitize=$GFEC_SANITIZE"
         -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=$GFEC_SANITIZE")
fi
cmake -S "$project" -B "$project/build" -G "$generator" -DCMAKE_PREFIX_PATH="$root/usr" "${flags[@]}" \
  >"$work/configure.log" 2>&1 || fail "configuring against the package: $(cat "$work/configure.log")"
grep -q "gfec_DIR:PATH=$root/usr/lib/cmake/gfec" "$project/build/CMakeCache.txt" ||
  fail "the project found another gfec: $(grep gfec_DIR "$project/build/CMakeCache.txt")"
cmake --build "$project/build" --target firmware runtime_user >"$work/build.log" 2>&1 ||
  fail "building against the package: $(cat "$work/build.log")"
[ "$("$project/build/firmware")" = "###..#.#.#" ] || fail "firmware printed '$("$project/build/firmware")'"
[ "$("$project/build/runtime_user")" = "walldist=42" ] || fail "runtime_user: $("$project/build/runtime_user")"
echo "$(basename "$deb"): $(stat -c %s "$deb") bytes; extracted gfec compiled, tested and built a CMake project"
