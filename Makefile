# casteljau: the two README commands (`make demo`, `make test`) and the others.
# On a fresh Debian 12 machine every target first installs what is missing:
# with apt-get when run as root, else it prints the one apt-get line and stops.
# Python is always Debian's /usr/bin/python3 (the python3 first on PATH has no numpy).

SHELL := /bin/bash
PYTHON := /usr/bin/python3
JOBS ?= $(shell nproc)
export NODE_PATH := /usr/share/nodejs

# Build, test and demo dependencies (Debian package names).
PACKAGES := cmake ninja-build g++ pkgconf libgtest-dev libgmock-dev libbenchmark-dev \
  librapidcheck-dev libgmp-dev libeigen3-dev libcli11-dev nlohmann-json3-dev libfmt-dev libpugixml-dev \
  libfreetype-dev fonts-dejavu-core fonts-cantarell \
  libcairo2-dev poppler-utils emscripten python3-dev python3-numpy python3-scipy \
  python3-matplotlib python3-pytest python3-hypothesis python3-meshio \
  pybind11-dev python3-pybind11 chromium python3-ezdxf libocct-data-exchange-dev \
  ccache python3-pytest-xdist linuxcnc-uspace clang-14 libclang-rt-14-dev
# Checkers we did not write: chromium reads SVG in tests/svg/ (driven by npm's
# playwright-core, installed into tests/svg/node_modules by deps); python3-ezdxf
# reads and writes DXF in tests/python/test_dxf_ezdxf.py; OpenCASCADE
# (libocct-data-exchange-dev) reads IGES and STEP in tests/exchange/;
# LinuxCNC's interpreter (linuxcnc-uspace: /usr/bin/rs274) and npm's
# gcode-toolpath (cncjs's, installed into tests/gcode/node_modules by deps)
# read G-code in tests/gcode/. clang-14 and its runtime (libclang-rt-14-dev:
# libFuzzer, ASan, UBSan) build the fuzz targets of tests/fuzz/.
# Peers measured beside casteljau by `make bench`.
BENCH_PACKAGES := libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev \
  libtbb-dev libsisl-dev lib2geom-dev libdouble-conversion-dev libgsl-dev libboost-dev \
  cargo librust-kurbo-dev librust-lyon-geom-dev python3-svgelements

# Every tree is configured with the flags CI uses (-Werror here, -g1 in the
# presets), so that a developer's `make test` fills ccache with exactly the
# objects CI's fresh clone asks for (docs/development.md).
CMAKE_FLAGS := -DPython_EXECUTABLE=$(PYTHON) -DCASTELJAU_WERROR=ON
# The bench build never gets -Werror: at -O3 -march=native GCC 12 warns inside
# Eigen's AVX-512 packet code and libstdc++'s string concatenation
# (-Wmaybe-uninitialized, -Wstringop-overflow: flow-analysis false positives the
# -O2 builds of `make test` do not meet), and benchmarks are not what CI gates.
BENCH_CMAKE_FLAGS := -DPython_EXECUTABLE=$(PYTHON)

# $(call pytest_on,TREE): pytest (with $(PYTHON)) on TREE's Python module and
# CLI, the arguments to follow; `make test`, python-asan and coverage use it.
pytest_on = CASTELJAU_CLI=$(CURDIR)/$(1)/casteljau CASTELJAU_PYTHONPATH=$(CURDIR)/$(1)/python \
  $(PYTHON) -m pytest -q -p no:cacheprovider -n $(JOBS)

# $(call timed,PHASE,COMMAND): runs COMMAND, prints its wall time and adds it
# to out/phases.tsv, the table `make test` and `make check` end with.
define timed
	@started=$$(date +%s%N); ( $(2) ); status=$$?; \
	tenths=$$(( ($$(date +%s%N) - started) / 100000000 )); \
	mkdir -p out; printf '%s\t%d.%d\n' "$(1)" $$((tenths / 10)) $$((tenths % 10)) >> out/phases.tsv; \
	echo "== $(1): $$((tenths / 10)).$$((tenths % 10)) s"; exit $$status
endef

# ccache's counters at the start of a run, and the hits since then.
define ccache_start
	@rm -f out/phases.tsv; mkdir -p out
	@if command -v ccache >/dev/null; then ccache --print-stats > out/ccache-start.tsv; fi
endef
define report
	@echo "== phases (wall seconds, this machine: $$(nproc) cores) =="
	@awk -F'\t' '{ printf "  %-26s %7.1f\n", $$1, $$2; s += $$2 } END { printf "  %-26s %7.1f\n", "total", s }' out/phases.tsv
	@if command -v ccache >/dev/null && [ -f out/ccache-start.tsv ]; then \
	  ccache --print-stats | awk -F'\t' 'NR == FNR { start[$$1] = $$2; next } \
	    { now[$$1] = $$2 - start[$$1] } \
	    END { hits = now["direct_cache_hit"] + now["preprocessed_cache_hit"]; total = hits + now["cache_miss"]; \
	          if (total > 0) printf "== ccache: %d of %d compilations found in the cache (%.0f %%)\n", hits, total, 100 * hits / total; \
	          else print "== ccache: nothing compiled" }' out/ccache-start.tsv -; \
	fi
endef

.PHONY: all deps bench-deps build python asan wasm playground fuzz fuzz-build coverage python-asan test check demo bench bench-playground bench-publish clean

all: build

# Installs the missing packages of $(1) (apt-get as root, else prints the line).
define install_missing
	@missing=$$(for p in $(1); do dpkg-query -W -f='$${Status}\n' "$$p" 2>/dev/null | grep -q '^install ok installed' || echo "$$p"; done); \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ]; then \
	    echo "installing:" $$missing; \
	    apt-get update -q && DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends $$missing; \
	  else \
	    echo "missing Debian packages; install them with:"; \
	    echo "  sudo apt-get install -y --no-install-recommends" $$missing; exit 1; \
	  fi; \
	fi
endef

deps:
	$(call install_missing,$(PACKAGES))
	@[ -d tests/svg/node_modules/playwright-core ] || { cd tests/svg && npm ci --no-audit --no-fund --ignore-scripts; }
	@[ -d tests/gcode/node_modules/gcode-toolpath ] || { cd tests/gcode && npm ci --no-audit --no-fund --ignore-scripts; }
	@[ -d tests/playground/node_modules/playwright-core ] || { cd tests/playground && npm ci --no-audit --no-fund --ignore-scripts; }

bench-deps: deps
	$(call install_missing,$(BENCH_PACKAGES))

build: deps
	$(call timed,configure build/,cmake --preset default $(CMAKE_FLAGS) >/dev/null)
	$(call timed,build build/,cmake --build --preset default -j $(JOBS))

# The Python module (pybind11, /usr/bin/python3) in build/python/casteljau:
# PYTHONPATH=build/python /usr/bin/python3 -c "import casteljau". Install it
# with cmake --install build --component python --prefix PREFIX.
python: deps
	cmake --preset default $(CMAKE_FLAGS) >/dev/null
	cmake --build --preset default -j $(JOBS) --target casteljau_python
	@echo "make python: import it with PYTHONPATH=$(CURDIR)/build/python $(PYTHON)"

asan: deps
	$(call timed,configure build-asan/,cmake --preset asan $(CMAKE_FLAGS) >/dev/null)
	$(call timed,build build-asan/,cmake --build --preset asan -j $(JOBS))

# The core library with Debian's em++ (keeps it inside the C++ subset em++ accepts).
wasm: deps
	$(call timed,configure build-wasm/,cmake --preset wasm $(CMAKE_FLAGS) >/dev/null)
	$(call timed,build build-wasm/,cmake --build --preset wasm -j $(JOBS))

# The libFuzzer targets (tests/fuzz/, docs/fuzzing.md): clang with ASan and
# UBSan in build-fuzz/. `make test` runs each for a few seconds on its seeds;
# `make fuzz` for FUZZ_SECONDS each (default 60), growing out/fuzz/corpus/
# from run to run; what a fuzzer finds lands in out/fuzz/findings/NAME/.
# `make fuzz FUZZ_MODE=campaign` keeps going past findings (libFuzzer's fork
# mode) for the long runs; FUZZ_TARGETS="dxf font" runs some targets only.
FUZZ_SECONDS ?= 60
FUZZ_MODE ?=
FUZZ_TARGETS ?= $(patsubst build-fuzz/tests/fuzz/%_fuzzer,%,$(wildcard build-fuzz/tests/fuzz/*_fuzzer))
fuzz-build: deps
	$(call timed,configure build-fuzz/,cmake --preset fuzz $(CMAKE_FLAGS) >/dev/null)
	$(call timed,build build-fuzz/,cmake --build --preset fuzz -j $(JOBS))

fuzz: fuzz-build
	@set -o pipefail; for name in $(FUZZ_TARGETS); do \
	  echo "== fuzz $$name ($(FUZZ_SECONDS) s)"; \
	  bash tests/fuzz/run.sh build-fuzz/tests/fuzz/$${name}_fuzzer $$name $(FUZZ_SECONDS) $(CURDIR)/out/fuzz $(FUZZ_MODE) 2>&1 \
	    | grep -E '^stat::|^#[0-9]+ *DONE|ERROR|SUMMARY|artifact|INFO: exiting' || exit 1; \
	done

# The Python module built with AddressSanitizer + UBSan (build-asan/python)
# and the pytest suite run on it, the sanitizer runtimes preloaded into
# /usr/bin/python3 (docs/python.md): the numpy boundary checked too. Not part of `make
# test` (the instrumented module and its suite take minutes); leaks are not
# reported (CPython's own allocations would drown ours).
python-asan: asan
	cmake --build --preset asan -j $(JOBS) --target casteljau_python
	LD_PRELOAD="$$(g++ -print-file-name=libasan.so):$$(g++ -print-file-name=libubsan.so)" \
	  ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
	  $(call pytest_on,build-asan) tests/python

# Coverage (docs/coverage.md): the default tree's suites (C++, CLI, pytest)
# run in build-coverage/ (-O0, gcov's counters in our objects only), read by
# gcovr into out/coverage/ (index.html, coverage.json, uncovered.txt) and
# summarized per layer by tests/coverage/report.py. Not part of `make test`.
# The package tests are left out: they link the installed, instrumented
# archives into programs of their own, built without gcov's runtime.
COVERAGE_PACKAGES := gcovr
coverage: deps
	$(call install_missing,$(COVERAGE_PACKAGES))
	cmake --preset coverage $(CMAKE_FLAGS) >/dev/null
	cmake --build --preset coverage -j $(JOBS)
	find build-coverage -name '*.gcda' -delete
	cd build-coverage && ctest --output-on-failure -j $(JOBS) -LE python -E '^package\.'
	$(call pytest_on,build-coverage) tests/python
	rm -rf out/coverage && mkdir -p out/coverage
	gcovr --root . --object-directory build-coverage --filter 'src/' --filter 'include/' --filter 'cli/' \
	  --filter 'python/' --exclude-throw-branches --exclude-unreachable-branches -j $(JOBS) \
	  --json out/coverage/coverage.json
	gcovr --add-tracefile out/coverage/coverage.json --html-details out/coverage/index.html
	$(PYTHON) tests/coverage/report.py out/coverage/coverage.json --uncovered out/coverage/uncovered.txt
	@echo "make coverage: out/coverage/index.html, what no suite ran in out/coverage/uncovered.txt"

# The web playground (issue 19): the core and its bindings (wasm/) built by
# em++ in build-wasm/, with the page of playground/, copied to out/playground/.
# It is one folder of static files that works from file:// (the WebAssembly
# is embedded in casteljau.js): open out/playground/index.html.
playground: wasm
	rm -rf out/playground && mkdir -p out && cp -r build-wasm/playground out/playground
	@echo "make playground: open out/playground/index.html ($$(du -sk out/playground | cut -f1) kB, $$(cat out/playground/casteljau.js out/playground/index.html out/playground/*.css out/playground/js/*.js out/playground/js/views/*.js | gzip -9 | wc -c) bytes gzip)"

# The suites of the default tree: C++ (ctest; the Python suite, labelled
# python, runs through pytest itself so that its summary shows) and pytest.
# $(1): more labels for ctest to exclude (|slow).
define default_suites
	@echo "== C++ tests (build/) =="
	$(call timed,C++ tests build/,cd build && ctest --output-on-failure -j $(JOBS) -LE 'python$(1)')
	@echo "== Python tests (pytest with $(PYTHON): the module in build/python, the CLI build/casteljau, against scipy) =="
	$(call timed,pytest,$(call pytest_on,build) --durations=10 tests/python)
endef

# Every test: what CI runs. `make check` is the inner loop.
test: test-start build asan wasm fuzz-build
	$(call default_suites)
	@echo "== C++ tests under AddressSanitizer + UBSan (build-asan/) =="
	$(call timed,C++ tests build-asan/,cd build-asan && ctest --output-on-failure -j $(JOBS) -LE python)
	@echo "== core library built with em++, run under node; the playground in Chromium (build-wasm/) =="
	$(call timed,em++ tests build-wasm/,cd build-wasm && ctest --output-on-failure)
	@echo "== fuzz targets, a few seconds each on their seeds (build-fuzz/) =="
	$(call timed,fuzz smoke build-fuzz/,cd build-fuzz && ctest --output-on-failure -j $(JOBS))
	$(report)
	@echo "make test: all test suites passed (C++, pytest, sanitizers, em++ core, playground, fuzz smoke)"

# The inner loop: the default tree and its C++ and Python suites, without the
# C++ tests labelled slow (over 10 s each); `make test` runs them all.
check: test-start build
	$(call default_suites,|slow)
	$(report)
	@echo "make check: the default tree's suites passed (make test runs every suite)"

.PHONY: test-start
test-start:
	$(ccache_start)

# The gallery of seed figures, and the playground with a screenshot of each
# of its views (taken in Chromium by tests/playground/page_test.mjs) linked
# from the gallery's index.
demo: build playground
	rm -rf out/gallery.tmp && ./build/casteljau gallery out/gallery.tmp
	mkdir -p out/gallery.tmp/playground
	@if CASTELJAU_PLAYGROUND_SHOTS=$(CURDIR)/out/gallery.tmp/playground bash tests/playground/run.sh out/playground build/casteljau examples >out/playground-shots.log 2>&1; then \
	  sed -i 's|</body>|<p><a href="playground/index.html">The web playground, view by view</a> (screenshots; the page itself: out/playground/index.html)</p>\n</body>|' out/gallery.tmp/index.html; \
	else echo "make demo: no playground screenshots (Chromium's run: out/playground-shots.log)"; rm -rf out/gallery.tmp/playground; fi
	rm -rf out/gallery && mv out/gallery.tmp out/gallery
	@echo "make demo: gallery written to out/gallery/index.html ($$(ls out/gallery/*.svg | wc -l) SVG, $$(ls out/gallery/*.png | wc -l) PNG, $$(ls out/gallery/playground/*.png 2>/dev/null | wc -l) playground views)"
	@echo "make demo: the playground is out/playground/index.html (open it in a browser; it works from file://)"

# Builds build-bench/ and runs bench/run.sh: out/bench/results.json and
# out/bench/RESULTS.md (the build time is reported there too).
bench: bench-deps
	@started=$$(date +%s); \
	cmake --preset bench $(BENCH_CMAKE_FLAGS) >/dev/null && \
	cmake --build --preset bench -j $(JOBS) && \
	CASTELJAU_BENCH_BUILD_SECONDS=$$(( $$(date +%s) - started )) bash bench/run.sh

# The playground's redraw time while dragging, measured in Chromium
# (bench/playground_frames.mjs): out/bench/playground_frames.md.
bench-playground: playground
	mkdir -p out/bench
	node bench/playground_frames.mjs out/playground out/bench/playground_frames.md

# Publishes the last `make bench` run: out/bench/RESULTS.md becomes
# docs/RESULTS.md and its summary the README's performance table.
bench-publish:
	@test -f out/bench/RESULTS.md || { echo "no out/bench/RESULTS.md: run make bench first"; exit 1; }
	cp out/bench/RESULTS.md docs/RESULTS.md
	$(PYTHON) bench/report.py readme --results docs/RESULTS.md --readme README.md

clean:
	rm -rf build build-asan build-wasm build-fuzz build-coverage build-bench out
