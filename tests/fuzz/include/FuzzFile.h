// The readers take file names: a fuzz input is written to a file of this process first.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

namespace medial::fuzz {

inline std::string writeInput(const uint8_t* data, size_t size, const std::string& extension) {
  const std::string path = "/tmp/medial-fuzz-" + std::to_string(::getpid()) + extension;
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

}  // namespace medial::fuzz
