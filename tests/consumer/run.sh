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
