# Rust benchmark peers (kurbo 0.7, lyon_geom 0.15) as a static library with a
# C ABI (rust_peers.h), built by cargo from Debian's librust-kurbo-dev and
# librust-lyon-geom-dev sources, offline. include()d from bench/CMakeLists.txt;
# defines the INTERFACE target casteljau_peer_rust, or nothing (with a STATUS
# line) when cargo or the crates are missing: the peer is optional.
#
# Cargo finds .cargo/config.toml (the Debian directory source) only from its
# working directory upwards, and writes Cargo.lock beside the manifest. So the
# crate is copied to ${CMAKE_CURRENT_BINARY_DIR}/rust_peers_crate and cargo
# runs there: the lock file and the build stay out of the source tree.

set(_rp_src ${CMAKE_CURRENT_LIST_DIR}/rust_peers)
set(_rp_crate ${CMAKE_CURRENT_BINARY_DIR}/rust_peers_crate)
set(_rp_target ${CMAKE_CURRENT_BINARY_DIR}/rust_peers)
set(_rp_registry /usr/share/cargo/registry)
set(_rp_lib ${_rp_target}/release/${CMAKE_STATIC_LIBRARY_PREFIX}casteljau_rust_peers${CMAKE_STATIC_LIBRARY_SUFFIX})

# Debian's cargo first (what a fresh Debian 12 CI has), then any on PATH.
find_program(CASTELJAU_CARGO cargo PATHS /usr/bin NO_DEFAULT_PATH)
find_program(CASTELJAU_CARGO cargo)
if(NOT CASTELJAU_CARGO)
  message(STATUS "bench peer: Rust (kurbo, lyon_geom) skipped: no cargo")
  return()
endif()
# The rustc beside that cargo, not one that PATH finds first (e.g. rustup's).
get_filename_component(_rp_bindir ${CASTELJAU_CARGO} DIRECTORY)
find_program(CASTELJAU_RUSTC rustc PATHS ${_rp_bindir} NO_DEFAULT_PATH)
find_program(CASTELJAU_RUSTC rustc)
find_package(Threads QUIET)
if(NOT CASTELJAU_RUSTC OR NOT Threads_FOUND OR NOT IS_DIRECTORY ${_rp_registry})
  message(STATUS "bench peer: Rust (kurbo, lyon_geom) skipped: no rustc, threads or ${_rp_registry}")
  return()
endif()

# -C target-cpu=native: the C++ benchmarks use -march=native, so the Rust
# peers get the same instruction set for a fair comparison.
set(_rp_env ${CMAKE_COMMAND} -E env CARGO_TARGET_DIR=${_rp_target} RUSTC=${CASTELJAU_RUSTC}
    "RUSTFLAGS=-C target-cpu=native")

# Manifest and config are copied at configure time (an edit reconfigures);
# resolving the lock file offline here also tells whether every crate is in
# the registry, so a missing one drops the peer instead of failing the build.
configure_file(${_rp_src}/Cargo.toml ${_rp_crate}/Cargo.toml COPYONLY)
configure_file(${_rp_src}/.cargo/config.toml ${_rp_crate}/.cargo/config.toml COPYONLY)
if(NOT EXISTS ${_rp_crate}/Cargo.lock OR ${_rp_crate}/Cargo.toml IS_NEWER_THAN ${_rp_crate}/Cargo.lock)
  file(MAKE_DIRECTORY ${_rp_crate}/src)
  execute_process(COMMAND ${_rp_env} ${CASTELJAU_CARGO} generate-lockfile --offline
                  WORKING_DIRECTORY ${_rp_crate}
                  RESULT_VARIABLE _rp_rc OUTPUT_QUIET ERROR_VARIABLE _rp_err)
  if(NOT _rp_rc EQUAL 0)
    file(REMOVE ${_rp_crate}/Cargo.lock)
    string(REGEX REPLACE "\n.*" "" _rp_err "${_rp_err}")
    message(STATUS "bench peer: Rust (kurbo, lyon_geom) skipped: ${_rp_err}")
    return()
  endif()
endif()

# Sources are copied at build time (flat src/, one lib.rs for now), then cargo
# builds the staticlib with the lock file above, offline (--frozen).
file(GLOB _rp_sources CONFIGURE_DEPENDS ${_rp_src}/src/*.rs)
add_custom_command(
  OUTPUT ${_rp_lib}
  COMMAND ${CMAKE_COMMAND} -E copy_if_different ${_rp_sources} ${_rp_crate}/src/
  COMMAND ${_rp_env} ${CASTELJAU_CARGO} build --release --frozen --quiet
  WORKING_DIRECTORY ${_rp_crate}
  DEPENDS ${_rp_sources} ${_rp_crate}/Cargo.toml ${_rp_crate}/Cargo.lock
          ${_rp_crate}/.cargo/config.toml
  COMMENT "cargo: Rust bench peers (kurbo, lyon_geom)"
  VERBATIM)
add_custom_target(casteljau_rust_peers_build DEPENDS ${_rp_lib})

add_library(casteljau_peer_rust INTERFACE)
# Dependencies of an INTERFACE library pass to whatever links it.
add_dependencies(casteljau_peer_rust casteljau_rust_peers_build)
target_include_directories(casteljau_peer_rust INTERFACE ${CMAKE_CURRENT_LIST_DIR})
# What a Rust staticlib needs from the system (rustc --print native-static-libs:
# gcc_s pthread m dl rt util c; on glibc 2.34+ rt and util live in libc).
target_link_libraries(casteljau_peer_rust INTERFACE ${_rp_lib} Threads::Threads ${CMAKE_DL_LIBS} m)
target_compile_definitions(casteljau_peer_rust INTERFACE CASTELJAU_HAVE_RUST_PEERS=1)
message(STATUS "bench peer: Rust (kurbo 0.7, lyon_geom 0.15) with ${CASTELJAU_CARGO}")
