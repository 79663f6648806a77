#!/usr/bin/env bash
# The README's command-line examples, run verbatim: the ```sh block under
# "## The command line" in README.md, each line as written, in a scratch
# folder where build/casteljau is the binary under test and examples/ the
# repository's examples folder. Each line must exit 0 with nothing on stderr,
# write the file it names after -o (non-empty; the gallery its index.html),
# and print what its comment shows when the comment is an output (a CSV line
# of numbers, as "# 2.25,1.5"). Editing the README edits this test.
# Usage: bash readme_examples.sh CASTELJAU EXAMPLES_DIR
source "$(dirname "$0")/support/common.sh" "$@"
readme="$examples/../README.md"

# The block: from the first ```sh line after the heading to the next ```.
mapfile -t lines < <(awk '/^## The command line/ {section = 1; next}
                          section && /^```sh$/ {inside = 1; next}
                          inside && /^```/ {exit}
                          inside && NF {print}' "$readme")
if [[ ${#lines[@]} -eq 0 ]]; then
  echo "FAIL: no \`\`\`sh block under '## The command line' in $readme"
  exit 1
fi

scratch="$work/readme"
mkdir -p "$scratch/build"
ln -s "$casteljau" "$scratch/build/casteljau"
ln -s "$(cd "$examples" && pwd)" "$scratch/examples"

# Under AddressSanitizer the gallery alone takes about 50 s of CPU, and
# tests/cli/gallery_index.sh already renders it there: a sanitizer build
# skips the gallery line (the default build runs every line).
sanitized=false
if ldd "$casteljau" 2>/dev/null | grep -q 'libasan'; then sanitized=true; fi

for line in "${lines[@]}"; do
  read -ra words <<<"${line%%#*}"
  if $sanitized && [[ "${words[1]:-}" == "gallery" ]]; then
    echo "skipped under the sanitizer (gallery_index.sh renders the gallery): $line"
    continue
  fi
  (cd "$scratch" && bash -c "$line") >"$work/stdout" 2>"$work/stderr" </dev/null
  status=$?
  if [[ $status -ne 0 || -s "$work/stderr" ]]; then
    echo "FAIL: README: $line"
    echo "  exit $status, stderr: $(head -c 500 "$work/stderr")"
    failures=$((failures + 1))
    continue
  fi
  # The comment, when it is an output: the expected standard output.
  comment=$(sed -nE 's/.*#[[:space:]]*([-+0-9.e,]+)[[:space:]]*$/\1/p' <<<"$line")
  if [[ -n "$comment" && "$(cat "$work/stdout")" != "$comment" ]]; then
    echo "FAIL: README: $line"
    echo "  printed $(head -c 200 "$work/stdout"), the comment says $comment"
    failures=$((failures + 1))
  fi
  for ((k = 0; k < ${#words[@]}; ++k)); do
    if [[ "${words[k]}" == "-o" && ! -s "$scratch/${words[k + 1]}" ]]; then
      echo "FAIL: README: $line"
      echo "  wrote no ${words[k + 1]}"
      failures=$((failures + 1))
    fi
  done
  if [[ "${words[1]}" == "gallery" && ! -s "$scratch/${words[2]:-out/gallery}/index.html" ]]; then
    echo "FAIL: README: $line"
    echo "  wrote no ${words[2]:-out/gallery}/index.html"
    failures=$((failures + 1))
  fi
done

finish "readme_examples (${#lines[@]} commands)"
