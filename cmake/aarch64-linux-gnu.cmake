# A CMake toolchain for 64-bit Arm Linux (aarch64), cross-compiled with Debian's cross compiler
# (g++-aarch64-linux-gnu) against a sysroot: the arm64 packages of the libraries the project
# uses, unpacked into one folder (tools/ports/aarch64.sh makes it). The test programs run under
# qemu-user, which CTest puts in front of each of them (CMAKE_CROSSCOMPILING_EMULATOR).
#
#   cmake -S . -B build-aarch64 --toolchain cmake/aarch64-linux-gnu.cmake \
#     -DPT_AARCH64_SYSROOT=/path/to/sysroot
#
# The sysroot can also come from the environment variable of the same name.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)

if(NOT PT_AARCH64_SYSROOT AND DEFINED ENV{PT_AARCH64_SYSROOT})
  set(PT_AARCH64_SYSROOT "$ENV{PT_AARCH64_SYSROOT}")
endif()
if(NOT PT_AARCH64_SYSROOT OR NOT EXISTS "${PT_AARCH64_SYSROOT}/usr")
  message(FATAL_ERROR "aarch64 toolchain: PT_AARCH64_SYSROOT ('${PT_AARCH64_SYSROOT}') must name a "
                      "folder holding the arm64 packages' usr/ (tools/ports/aarch64.sh makes one)")
endif()
set(PT_AARCH64_SYSROOT "${PT_AARCH64_SYSROOT}" CACHE PATH "The arm64 packages, unpacked")
# The checks CMake compiles in a project of their own read this file again: pass the sysroot on.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES PT_AARCH64_SYSROOT)

set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)

# Libraries, headers and package configs come from the sysroot only; programs (pkg-config, qemu)
# from the machine that builds.
set(CMAKE_FIND_ROOT_PATH "${PT_AARCH64_SYSROOT}")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# pkg-config answers for the sysroot's .pc files, with their paths moved into it.
set(ENV{PKG_CONFIG_LIBDIR}
    "${PT_AARCH64_SYSROOT}/usr/lib/aarch64-linux-gnu/pkgconfig:${PT_AARCH64_SYSROOT}/usr/share/pkgconfig")
set(ENV{PKG_CONFIG_SYSROOT_DIR} "${PT_AARCH64_SYSROOT}")

# The cross compiler has its own C library; the shared libraries the project links (oneTBB,
# pugixml) and those they need are found in the sysroot at the link.
foreach(dir usr/lib/aarch64-linux-gnu lib/aarch64-linux-gnu)
  string(APPEND CMAKE_EXE_LINKER_FLAGS_INIT " -Wl,-rpath-link,${PT_AARCH64_SYSROOT}/${dir}")
  string(APPEND CMAKE_SHARED_LINKER_FLAGS_INIT " -Wl,-rpath-link,${PT_AARCH64_SYSROOT}/${dir}")
  string(APPEND CMAKE_MODULE_LINKER_FLAGS_INIT " -Wl,-rpath-link,${PT_AARCH64_SYSROOT}/${dir}")
endforeach()

# Programs run under qemu-user, with the sysroot as their root for the dynamic loader and the
# shared libraries.
find_program(PT_QEMU_AARCH64 NAMES qemu-aarch64-static qemu-aarch64)
if(PT_QEMU_AARCH64)
  set(CMAKE_CROSSCOMPILING_EMULATOR "${PT_QEMU_AARCH64};-L;${PT_AARCH64_SYSROOT}")
endif()
