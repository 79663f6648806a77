#!/usr/bin/env bash
# ctest: install the build tree into a temporary prefix as a user would, then
# check the package from outside: what is installed (no internal targets, no
# Python in the C++ prefix), every C++ example of the README and docs/cpp.md
# compiled and run, every header compiled alone, find_package components,
# pkg-config, and the Python package installed by its own component.
set -euo pipefail
build_dir=$1 source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "consumer: $*" >&2; exit 1; }

prefix=$work/prefix
# Every compile below goes through ccache when it is installed, with paths
# relative to the temporary folder, so that the next run (in another
# temporary folder) finds what this one compiled.
if command -v ccache >/dev/null; then
  export CMAKE_CXX_COMPILER_LAUNCHER=ccache CCACHE_BASEDIR=$work CCACHE_NOHASHDIR=true
fi
cmake --install "$build_dir" --prefix "$prefix" >/dev/null
[ -e "$prefix/include/casteljau/casteljau.hpp" ] || fail "no umbrella header installed"
[ -e "$prefix/include/casteljau/version.hpp" ] || fail "no version header installed"
if grep -q -E 'casteljau_(eigen|options)|Eigen3' "$prefix"/lib/cmake/casteljau/*.cmake; then
  fail "the exported package names an internal target or Eigen"
fi
if find "$prefix" -name '*.py' -o -name 'site-packages' | grep -q .; then
  fail "the C++ install put Python files in the prefix"
fi

# The examples, the headers alone, then run every example from the source
# folder (they read examples/head.csv and the like).
/usr/bin/python3 "$source_dir/tests/consumer/extract_examples.py" "$work/examples" \
  "$source_dir/README.md" "$source_dir/docs/cpp.md"
cmake -S "$source_dir/tests/consumer" -B "$work/build" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" \
  -DCASTELJAU_EXAMPLES="$work/examples" | grep '^-- consumer:'
cmake --build "$work/build" >/dev/null || { cmake --build "$work/build" 2>&1 | grep -E 'error|FAILED' | head -20; fail "build failed"; }
for source in "$work"/examples/*.cpp; do
  name=$(basename "$source" .cpp)
  (cd "$source_dir" && "$work/build/$name" >"$work/$name.out") || { cat "$work/$name.out"; fail "example $name failed"; }
  if [ -e "$work/examples/$name.expected" ]; then
    diff -u "$work/examples/$name.expected" "$work/$name.out" || fail "example $name does not print the output its page shows"
    echo "ran $name, its output as shown"
  else
    echo "ran $name"
  fi
done

# Components: core alone (no fmt, no io), io; a component that does not exist is refused by name.
for component in core io; do
  cmake -S "$source_dir/tests/consumer/components" -B "$work/components_$component" -G Ninja \
    -DCMAKE_PREFIX_PATH="$prefix" -DCOMPONENT=$component >/dev/null
  cmake --build "$work/components_$component" >/dev/null
  "$work/components_$component/notebook_point" >/dev/null
done
if cmake -S "$source_dir/tests/consumer/components" -B "$work/components_bad" -G Ninja \
  -DCMAKE_PREFIX_PATH="$prefix" -DCOMPONENT=nurbs >"$work/bad.log" 2>&1; then
  fail "COMPONENTS nurbs was accepted"
fi
grep -q "casteljau has no component 'nurbs' here" "$work/bad.log" || { cat "$work/bad.log"; fail "no message for a missing component"; }
echo "components: core, io; nurbs refused"

# pkg-config, the README's library example compiled by hand.
export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
first_example=$(ls "$work"/examples/README_*.cpp | head -1)
# shellcheck disable=SC2046
c++ "$first_example" -o "$work/pkgconfig_example" $(pkg-config --cflags --libs casteljau)
(cd "$source_dir" && "$work/pkgconfig_example" >/dev/null)
echo "pkg-config: $(pkg-config --modversion casteljau), $(basename "$first_example") built with c++ \$(pkg-config --cflags --libs casteljau)"

# The Python package goes only where its own component is asked to.
if [ -e "$build_dir/python/casteljau" ]; then
  cmake --install "$build_dir" --component python --prefix "$work/python" >/dev/null
  site=$(echo "$work"/python/lib/python3*/site-packages)
  PYTHONPATH=$site /usr/bin/python3 -c "import casteljau; print('python component:', casteljau.__version__)"
fi

# The course companion's C++ programs (examples/course/cpp): their own CMake
# project against the same prefix, warnings as errors on top of its -Wall
# -Wextra; each program runs from outside the source folder into a fresh
# output folder (the data folder is head_and_car's second argument, the
# others ignore it), must succeed, print its known result and write its files.
course=$work/course
cmake -S "$source_dir/examples/course/cpp" -B "$course/build" -G Ninja -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_CXX_FLAGS=-Werror >"$course.log" 2>&1 || { cat "$course.log"; fail "course programs: configure failed"; }
cmake --build "$course/build" >"$course.log" 2>&1 || { grep -E 'warning|error|FAILED' "$course.log" | head -20; fail "course programs: build failed"; }
check_course() {  # program, a line its output must hold, the files it must write
  local program=$1 expected=$2 file
  shift 2
  (cd "$work" && "$course/build/$program" "$course/out" "$source_dir/examples" >"$course/$program.out" 2>&1) ||
    { cat "$course/$program.out"; fail "course program $program failed"; }
  grep -qF "$expected" "$course/$program.out" || { cat "$course/$program.out"; fail "course program $program does not print '$expected'"; }
  for file in "$@"; do
    [ -s "$course/out/$file" ] || fail "course program $program did not write $file"
  done
  echo "course: ran $program, wrote $*"
}
check_course de_casteljau "B(0.5) = (2.25, 1.5)" de_casteljau.svg
check_course head_and_car "head: 19 points, 18 pieces" head_and_car.svg
check_course bspline_basis "u = 4    N_0..N_6 = 0.0000 0.0000 0.0000 0.0000 0.0000 0.0000 1.0000" bspline_basis.svg
check_course coons_patch "P(0.5, 0.5) = (0.5, 0.5, 0.3375)" coons_patch.obj coons_patch.svg
