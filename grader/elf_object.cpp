#include "grader/elf_object.h"

#include <elf.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace fs = std::filesystem;

namespace pt::grader {

std::string read_binary(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot be read");
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::vector<CodeSection> code_sections(const std::string& image, const fs::path& path) {
  auto bad = [&](const std::string& why) {
    return std::runtime_error(path.string() + ": not an ELF64 relocatable object (" + why + ")");
  };
  if (image.size() < sizeof(Elf64_Ehdr) || std::memcmp(image.data(), ELFMAG, SELFMAG) != 0)
    throw bad("no ELF header");
  Elf64_Ehdr eh;
  std::memcpy(&eh, image.data(), sizeof eh);
  if (eh.e_ident[EI_CLASS] != ELFCLASS64) throw bad("not 64-bit");
  if (eh.e_type != ET_REL) throw bad("not relocatable");
  if (eh.e_shentsize != sizeof(Elf64_Shdr) || eh.e_shoff == 0 || eh.e_shoff > image.size() ||
      size_t(eh.e_shnum) * sizeof(Elf64_Shdr) > image.size() - eh.e_shoff)
    throw bad("section headers out of the file");
  std::vector<Elf64_Shdr> sh(eh.e_shnum);
  std::memcpy(sh.data(), image.data() + eh.e_shoff, sh.size() * sizeof(Elf64_Shdr));
  auto inside = [&](const Elf64_Shdr& s) {
    return s.sh_offset <= image.size() && s.sh_size <= image.size() - s.sh_offset;
  };
  const Elf64_Shdr* names = eh.e_shstrndx < sh.size() ? &sh[eh.e_shstrndx] : nullptr;
  std::vector<CodeSection> code(sh.size());
  for (size_t i = 0; i < sh.size(); ++i) {
    const Elf64_Shdr& s = sh[i];
    if (s.sh_type != SHT_PROGBITS || !(s.sh_flags & SHF_EXECINSTR) || !inside(s)) continue;
    CodeSection& c = code[i];
    if (names && inside(*names) && s.sh_name < names->sh_size)
      c.name = std::string(image.c_str() + names->sh_offset + s.sh_name);
    c.bytes = reinterpret_cast<const unsigned char*>(image.data()) + s.sh_offset;
    c.size = s.sh_size;
    c.in_group = (s.sh_flags & SHF_GROUP) != 0;
    c.relocated.assign(c.size, false);
  }
  for (const Elf64_Shdr& s : sh) {
    if ((s.sh_type != SHT_RELA && s.sh_type != SHT_REL) || !inside(s) || s.sh_info >= code.size() ||
        !code[s.sh_info].bytes)
      continue;
    const size_t entry = s.sh_type == SHT_RELA ? sizeof(Elf64_Rela) : sizeof(Elf64_Rel);
    CodeSection& c = code[s.sh_info];
    for (size_t at = 0; at + entry <= s.sh_size; at += entry) {
      Elf64_Rel r;  // r_offset opens both kinds
      std::memcpy(&r, image.data() + s.sh_offset + at, sizeof r);
      for (size_t k = 0; k < 8 && r.r_offset + k < c.size; ++k) c.relocated[r.r_offset + k] = true;
    }
  }
  std::vector<CodeSection> out;
  for (CodeSection& c : code)
    if (c.bytes) out.push_back(std::move(c));
  return out;
}


std::string link_time_code_in(const fs::path& path) {
  std::string image;
  try {
    image = read_binary(path);
    code_sections(image, path);  // an ELF64 relocatable object, or the reason it is not
  } catch (const std::exception& e) {
    return e.what();
  }
  Elf64_Ehdr eh;
  std::memcpy(&eh, image.data(), sizeof eh);
  std::vector<Elf64_Shdr> sh(eh.e_shnum);
  std::memcpy(sh.data(), image.data() + eh.e_shoff, sh.size() * sizeof(Elf64_Shdr));
  if (eh.e_shstrndx >= sh.size()) return path.string() + ": its sections have no names";
  const Elf64_Shdr& names = sh[eh.e_shstrndx];
  if (names.sh_offset > image.size() || names.sh_size > image.size() - names.sh_offset)
    return path.string() + ": its section names are out of the file";
  for (const Elf64_Shdr& s : sh) {
    if (s.sh_name >= names.sh_size) return path.string() + ": a section's name is out of its table";
    const char* at = image.data() + names.sh_offset + s.sh_name;
    const std::string name(at, strnlen(at, names.sh_size - s.sh_name));
    for (const char* prefix : {".gnu.lto", ".gnu.debuglto", ".llvm"})
      if (name.rfind(prefix, 0) == 0)
        return path.string() + ": it holds link-time code (section " + name + ")";
  }
  return "";
}

}  // namespace pt::grader
