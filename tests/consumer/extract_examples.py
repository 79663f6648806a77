"""Writes every ```cpp block of the given Markdown files to OUT/<file>_<n>.cpp.

The consumer test (run.sh) compiles and runs each against the installed
package, so a C++ example in the README or docs/cpp.md that does not compile,
or whose program fails, fails CI. Every ```cpp block is a whole program (it
has a main); a fragment that is not meant to compile is fenced as ```c++.
When the block is followed by a line "Output:" and a ```text block, that text
is written to OUT/<file>_<n>.expected and run.sh requires the program to print
exactly it, so an output shown in the docs is the output the program gives.
"""
import pathlib
import re
import sys


def main() -> int:
    out = pathlib.Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    count = 0
    for name in sys.argv[2:]:
        path = pathlib.Path(name)
        text = path.read_text(encoding="utf-8")
        blocks = re.findall(r"^```cpp\n(.*?)^```$\n(?:\nOutput:\n\n```text\n(.*?)^```$)?", text, re.S | re.M)
        for n, (block, expected) in enumerate(blocks, 1):
            if not re.search(r"\bint main\(", block):
                print(f"{path}: C++ example {n} has no main(); fence a fragment as ```c++", file=sys.stderr)
                return 1
            (out / f"{path.stem}_{n}.cpp").write_text(block, encoding="utf-8")
            if expected:
                (out / f"{path.stem}_{n}.expected").write_text(expected, encoding="utf-8")
            count += 1
    print(f"{count} C++ examples from {', '.join(sys.argv[2:])}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
