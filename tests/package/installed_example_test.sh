#!/bin/sh
# The installed package as a program of its own sees it (docs/api.md): `cmake --install`
# into a fresh prefix, the installed `twb` runs from there, and examples/cpp, a separate
# CMake project, finds the package with find_package(twb), compiles against the installed
# public headers alone and links twb::twb. Its distress load must be the installed
# command's to the last digit written: the same library, the same numbers.
#
# With PYTHON, the installed Python module too: it imports from the prefix (finding the
# installed libtwb, not the build's) and its point is the installed command's.
#
#   installed_example_test.sh BUILD_DIR SOURCE_DIR [PYTHON]
set -eu
build=$1
source=$2
python=${3:-}
work=$build/installed-example
rm -rf "$work"
mkdir -p "$work"

cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
# Only the public headers are installed: anything else would be an API by accident.
installed=$(cd "$work/prefix/include" && find twb -name '*.h' | sort)
public=$(cd "$source/include" && find twb -name '*.h' | sort)
if [ "$installed" != "$public" ]; then
  echo "installed headers differ from include/twb:"; echo "$installed"; exit 1
fi
# Self-contained: the public headers include the standard library and each other, nothing
# else (a dependency's header would compile here, where Debian's are all installed, and
# fail for a user without them).
foreign=$(grep -rhE '^ *# *include' "$work/prefix/include/twb" | grep -vE '<[a-z_]+>|"twb/' || true)
if [ -n "$foreign" ]; then echo "public headers include more than the standard library and twb:"; echo "$foreign"; exit 1; fi
"$work/prefix/bin/twb" --version

cmake -S "$source/examples/cpp" -B "$work/example" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_BUILD_TYPE=Release > "$work/configure.log"
cmake --build "$work/example" > "$work/build.log"

scene=$source/configs/jackson_green_2006.yaml
"$work/example/washer_points" "$scene" 60 120 180 > "$work/example.txt"
cat "$work/example.txt"
"$work/prefix/bin/twb" run "$scene" --set study.error_estimate=none --out "$work/cli" --quiet > /dev/null

# The example prints W_d with %.17g; distress.csv holds it to ten significant digits.
example_wd=$(sed -n 's/^distress at .*: \([0-9.e+-]*\) N$/\1/p' "$work/example.txt")
cli_wd=$(awk -F, 'NR == 1 { for (k = 1; k <= NF; ++k) if ($k == "W_d_N") c = k } NR == 2 { print $c }' \
  "$work/cli/distress.csv")
if [ -z "$example_wd" ] || [ -z "$cli_wd" ]; then
  echo "no distress load: example '$example_wd', twb run '$cli_wd'"; exit 1
fi
example_10=$(printf '%.10g' "$example_wd")
if [ "$example_10" != "$cli_wd" ]; then
  echo "W_d differs: example $example_wd ($example_10), twb run $cli_wd"; exit 1
fi
# Three solved loads, each a row of numbers.
rows=$(grep -cE '^ +[0-9.]+ +[0-9.e+-]+ +[0-9.]+ +[0-9.]+ +[0-9.]+ +[0-9]+$' "$work/example.txt")
if [ "$rows" -ne 3 ]; then echo "expected 3 solved loads, found $rows"; exit 1; fi
echo "installed package: example and twb run agree, W_d = $cli_wd N"

if [ -n "$python" ]; then
  module=$(find "$work/prefix" -name '_twb*.so')
  [ -n "$module" ] || { echo "the Python module was not installed"; exit 1; }
  site=$(dirname "$(dirname "$module")")
  "$work/prefix/bin/twb" run "$scene" --set operating.load="150 N" --set 'study={type: point}' \
    --out "$work/cli-point" --quiet > /dev/null
  cli_feff=$(awk -F, 'NR == 1 { for (k = 1; k <= NF; ++k) if ($k == "f_eff") c = k } NR == 2 { print $c }' \
    "$work/cli-point/states.csv")
  # Only the prefix on the path, and the build's library out of reach.
  py_feff=$(cd "$work" && env -u LD_LIBRARY_PATH PYTHONPATH="$site" "$python" -c "
import twb, os
assert twb.__file__.startswith('$site'), twb.__file__
r = twb.run('$scene', overrides={'operating.load': '150 N', 'study': {'type': 'point'}})
print('%.10g' % r.states['f_eff'][0])")
  if [ "$py_feff" != "$cli_feff" ]; then echo "f_eff differs: module $py_feff, twb run $cli_feff"; exit 1; fi
  # twb.run writes the scene's output.directory, relative to where it runs, as twb run does.
  [ -f "$work/results/jackson_green_2006/run.json" ] || { echo "twb.run wrote no results directory"; exit 1; }
  ldd "$module" | grep -q "$work/prefix" || { echo "the module does not load the installed libtwb:"; ldd "$module"; exit 1; }
  echo "installed Python module: f_eff = $py_feff at 150 N, as twb run"
fi
