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
  pybind11-dev python3-pybind11 chromium python3-ezdxf libocct-data-exchange-dev
# Checkers we did not write: chromium reads SVG in tests/svg/ (driven by npm's
# playwright-core, installed into tests/svg/node_modules by deps); python3-ezdxf
# reads and writes DXF in tests/python/test_dxf_ezdxf.py; OpenCASCADE
# (libocct-data-exchange-dev) reads IGES and STEP in tests/exchange/.
# Peers measured beside casteljau by `make bench`.
BENCH_PACKAGES := libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev \
  libtbb-dev libsisl-dev lib2geom-dev libdouble-conversion-dev libgsl-dev libboost-dev \
  cargo librust-kurbo-dev librust-lyon-geom-dev python3-svgelements

CMAKE_FLAGS := -DPython_EXECUTABLE=$(PYTHON)
# The bench build never gets -Werror: at -O3 -march=native GCC 12 warns inside
# Eigen's AVX-512 packet code and libstdc++'s string concatenation
# (-Wmaybe-uninitialized, -Wstringop-overflow: flow-analysis false positives the
# -O2 builds of `make test` do not meet), and benchmarks are not what CI gates.
BENCH_CMAKE_FLAGS := $(CMAKE_FLAGS)
# CI also keeps only line tables in the -O2 build (-g1: backtraces still name
# file and line): full debug info is a third of its compile time, and CI
# has 2 cores and a time budget.
ifeq ($(CI),true)
  CMAKE_FLAGS += -DCASTELJAU_WERROR=ON "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG"
endif

.PHONY: all deps bench-deps build python asan wasm test demo bench bench-publish clean

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

bench-deps: deps
	$(call install_missing,$(BENCH_PACKAGES))

build: deps
	cmake --preset default $(CMAKE_FLAGS) >/dev/null
	cmake --build --preset default -j $(JOBS)

# The Python module (pybind11, /usr/bin/python3) in build/python/casteljau:
# PYTHONPATH=build/python /usr/bin/python3 -c "import casteljau". Install it
# with cmake --install build --component python --prefix PREFIX.
python: deps
	cmake --preset default $(CMAKE_FLAGS) >/dev/null
	cmake --build --preset default -j $(JOBS) --target casteljau_python
	@echo "make python: import it with PYTHONPATH=$(CURDIR)/build/python $(PYTHON)"

asan: deps
	cmake --preset asan $(CMAKE_FLAGS) >/dev/null
	cmake --build --preset asan -j $(JOBS)

# The core library with Debian's em++ (keeps it inside the C++ subset em++ accepts).
wasm: deps
	cmake --preset wasm $(CMAKE_FLAGS) >/dev/null
	cmake --build --preset wasm -j $(JOBS)

test: build asan wasm
	@echo "== C++ tests (build/) =="
	cd build && ctest --output-on-failure -j $(JOBS) -LE python
	@echo "== Python tests (pytest with $(PYTHON): the module in build/python, the CLI build/casteljau, against scipy) =="
	CASTELJAU_CLI=$(CURDIR)/build/casteljau CASTELJAU_PYTHONPATH=$(CURDIR)/build/python \
	  $(PYTHON) -m pytest -q -p no:cacheprovider tests/python
	@echo "== C++ tests under AddressSanitizer + UBSan (build-asan/) =="
	cd build-asan && ctest --output-on-failure -j $(JOBS) -LE python
	@echo "== core library built with em++, run under node (build-wasm/) =="
	cd build-wasm && ctest --output-on-failure
	@echo "make test: all test suites passed (C++, pytest, sanitizers, em++ core)"

demo: build
	rm -rf out/gallery.tmp && ./build/casteljau gallery out/gallery.tmp
	rm -rf out/gallery && mv out/gallery.tmp out/gallery
	@echo "make demo: gallery written to out/gallery/index.html ($$(ls out/gallery/*.svg | wc -l) SVG, $$(ls out/gallery/*.png | wc -l) PNG)"

# Builds build-bench/ and runs bench/run.sh: out/bench/results.json and
# out/bench/RESULTS.md (the build time is reported there too).
bench: bench-deps
	@started=$$(date +%s); \
	cmake --preset bench $(BENCH_CMAKE_FLAGS) >/dev/null && \
	cmake --build --preset bench -j $(JOBS) && \
	CASTELJAU_BENCH_BUILD_SECONDS=$$(( $$(date +%s) - started )) bash bench/run.sh

# Publishes the last `make bench` run: out/bench/RESULTS.md becomes
# docs/RESULTS.md and its summary the README's performance table.
bench-publish:
	@test -f out/bench/RESULTS.md || { echo "no out/bench/RESULTS.md: run make bench first"; exit 1; }
	cp out/bench/RESULTS.md docs/RESULTS.md
	$(PYTHON) bench/report.py readme --results docs/RESULTS.md --readme README.md

clean:
	rm -rf build build-asan build-wasm build-bench out
