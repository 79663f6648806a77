#!/bin/bash -eu
# OSS-Fuzz's build script (google.github.io/oss-fuzz, "new project guide"):
# builds every target of this folder with the compiler, flags and engine
# OSS-Fuzz gives ($CXX, $CXXFLAGS, $LIB_FUZZING_ENGINE), then copies each
# binary with its seed corpus (NAME_fuzzer_seed_corpus.zip) and dictionary
# (NAME_fuzzer.dict) to $OUT. Locally, the fuzz preset builds the same targets
# in build-fuzz/ with its own flags (make fuzz). Run from the repository root.
cmake -S . -B build-oss-fuzz -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER="$CXX" -DCMAKE_CXX_FLAGS="$CXXFLAGS" \
  -DCASTELJAU_FUZZ=ON -DCASTELJAU_FUZZ_INSTRUMENT=OFF -DCASTELJAU_FUZZ_ENGINE="$LIB_FUZZING_ENGINE" \
  -DCASTELJAU_BUILD_TESTS=OFF -DCASTELJAU_BUILD_CLI=OFF -DCASTELJAU_BUILD_RENDER=OFF \
  -DCASTELJAU_BUILD_PYTHON=OFF -DCASTELJAU_CCACHE=OFF
cmake --build build-oss-fuzz
for fuzzer in build-oss-fuzz/tests/fuzz/*_fuzzer; do
  name=$(basename "$fuzzer")
  target=${name%_fuzzer}
  cp "$fuzzer" "$OUT/$name"
  (cd "tests/fuzz/corpus/$target" && zip -q -r "$OUT/${name}_seed_corpus.zip" .)
  if [ -f "tests/fuzz/dictionaries/$target.dict" ]; then cp "tests/fuzz/dictionaries/$target.dict" "$OUT/$name.dict"; fi
done
