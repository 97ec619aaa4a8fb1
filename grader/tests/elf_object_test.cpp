// What the grader links of a student's: an object that carries link-time code (sections a
// linker's compiler plugin would compile with the grader's rights), or that is no relocatable
// object at all, is named; an ordinary object is not; a damaged one is read without harm.
#include "grader/elf_object.h"

#include <cstdlib>
#include <fstream>
#include <random>

#include <gtest/gtest.h>

#include "framework/testing/temp_folder.h"
#include "framework/testing/test_paths.h"

namespace fs = std::filesystem;

namespace pt::grader {
namespace {

/// Compiles `source` to an object with this build's compiler, as a student's file would be.
fs::path compiled(const test::TempFolder& dir, const std::string& name, const std::string& source) {
  const fs::path cpp = dir.path() / (name + ".cpp"), object = dir.path() / (name + ".o");
  std::ofstream(cpp) << source;
  const std::string command = std::string("'") + PT_CXX_COMPILER + "' -c -O2 -o '" +
                              object.string() + "' '" + cpp.string() + "' 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  return object;
}

TEST(ElfObject, AnOrdinaryObjectOnlyPlacesMachineCode) {
  test::TempFolder dir("pt-elf");
  const fs::path o = compiled(dir, "plain", "int twice(int x) { return 2 * x; }\n");
  EXPECT_EQ(link_time_code_in(o), "");
  bool found = false;
  const std::string image = read_binary(o);
  for (const CodeSection& c : code_sections(image, o)) found = found || (c.name == ".text" && c.size > 0);
  EXPECT_TRUE(found) << "no .text in a compiled function";
}

// What a student's file can write without any compiler flag: a top-level asm that makes the
// sections GCC's linker plugin takes for link-time code (or LLVM's bitcode section).
TEST(ElfObject, LinkTimeCodeSectionsAreNamed) {
  test::TempFolder dir("pt-elf");
  for (const char* section : {".gnu.lto_.symtab.0", ".gnu.lto_main.1.abc", ".llvmbc"}) {
    SCOPED_TRACE(section);
    const fs::path o = compiled(dir, "lto", std::string("int f() { return 1; }\nasm(\".section ") +
                                                section + ",\\\"e\\\",@progbits\\n.byte 1\\n"
                                                          ".previous\");\n");
    const std::string why = link_time_code_in(o);
    EXPECT_NE(why.find("holds link-time code"), std::string::npos) << why;
  }
}

TEST(ElfObject, WhatIsNoRelocatableObjectIsNamed) {
  test::TempFolder dir("pt-elf");
  std::ofstream(dir.path() / "script.o") << "INPUT(/etc/shadow)\n";
  EXPECT_NE(link_time_code_in(dir.path() / "script.o").find("not an ELF64 relocatable object"),
            std::string::npos);
  // A program is no relocatable object either.
  const fs::path program = fs::path(pt::test::binary_dir()) / "grader" / "grader";
  if (fs::exists(program)) {
    EXPECT_NE(link_time_code_in(program).find("not relocatable"), std::string::npos);
  }
}

// Objects cut short or with bytes changed anywhere are read within their bytes: each gives an
// answer ("" or a reason), never a crash (the grader reads them as root).
TEST(ElfObject, ADamagedObjectIsReadWithoutHarm) {
  test::TempFolder dir("pt-elf");
  const fs::path o = compiled(dir, "plain", "int twice(int x) { return 2 * x; }\n");
  const std::string image = read_binary(o);
  std::mt19937 rng(3);
  int refused = 0;
  for (int i = 0; i < 300; ++i) {
    std::string b = image;
    if (i % 3 == 0) {
      b.resize(rng() % b.size());
    } else {
      for (int k = 0; k < 1 + i % 8; ++k) b[rng() % b.size()] = char(rng());
    }
    const fs::path m = dir.path() / "damaged.o";
    std::ofstream(m, std::ios::binary | std::ios::trunc) << b;
    if (!link_time_code_in(m).empty()) ++refused;
  }
  EXPECT_GT(refused, 50);
}

}  // namespace
}  // namespace pt::grader
