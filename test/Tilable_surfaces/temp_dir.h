// Test helper: a fresh directory of its own under the system's temporary
// directory (mkdtemp, so concurrent tests and runs never share one), removed
// with everything in it when the object goes.
#ifndef TILABLE_SURFACES_TEST_TEMP_DIR_H
#define TILABLE_SURFACES_TEST_TEMP_DIR_H

#include <stdlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

class Temp_dir
{
public:
  /// A new empty directory whose name starts with `prefix`.
  explicit Temp_dir(const std::string& prefix)
  {
    std::string pattern =
      (std::filesystem::temp_directory_path() / ("tilable_surfaces_" + prefix + "_XXXXXX")).string();
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    if(mkdtemp(name.data()) == nullptr)
      throw std::runtime_error("mkdtemp failed for " + pattern);
    m_path = name.data();
  }
  ~Temp_dir()
  {
    std::error_code ignored;
    std::filesystem::remove_all(m_path, ignored);
  }
  Temp_dir(const Temp_dir&) = delete;
  Temp_dir& operator=(const Temp_dir&) = delete;

  const std::filesystem::path& path() const { return m_path; }
  operator const std::filesystem::path&() const { return m_path; }
  std::filesystem::path operator/(const std::string& name) const { return m_path / name; }

private:
  std::filesystem::path m_path;
};

#endif
