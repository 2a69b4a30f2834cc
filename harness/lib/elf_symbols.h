// Names for addresses in a firmware image, so a fault report says "bvb_sobel3x3_u8_asm+0x2a"
// rather than a bare PC.
#pragma once

#include <cstdint>
#include <string>

namespace bvb {

// "function+0xoffset" for an address inside a function of the ELF, else "".
std::string symbolize(const std::string &elf_path, uint32_t address);

// The value of a symbol (its C name, without the ABI's leading underscore); false if absent.
bool symbol_value(const std::string &elf_path, const std::string &name, uint32_t *value);

}  // namespace bvb
