// The reference figures of CGAL's fandisk at the defaults, read from data/fandisk.json:
// the one place every test language (C++, shell, Python, JavaScript) takes them from.
#ifndef FS_TEST_FANDISK_REFERENCE_H
#define FS_TEST_FANDISK_REFERENCE_H

#include <nlohmann/json.hpp>

#include <cstddef>
#include <fstream>
#include <stdexcept>
#include <string>

namespace fs_test {

// The figure `key` of data/fandisk.json (a non-negative integer); throws if the file or
// the key is missing, so a renamed figure fails the test that asks for it.
inline std::size_t fandisk_reference(const std::string& key)
{
  static const nlohmann::json figures = [] {
    std::ifstream in(std::string(FS_TEST_DATA_DIR) + "/fandisk.json");
    if(!in) throw std::runtime_error("cannot open " + std::string(FS_TEST_DATA_DIR) + "/fandisk.json");
    return nlohmann::json::parse(in);
  }();
  if(!figures.contains(key)) throw std::runtime_error("data/fandisk.json has no figure '" + key + "'");
  return figures.at(key).get<std::size_t>();
}

} // namespace fs_test

#endif // FS_TEST_FANDISK_REFERENCE_H
