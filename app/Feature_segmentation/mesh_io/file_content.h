// SPDX-License-Identifier: GPL-3.0-or-later
// The file buffer that the programs' file readers read from (File_content: the whole
// file in memory, mapped or read, after check_regular_file()) and the one error they all
// throw on bad input (Input_error).

#ifndef CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_FILE_CONTENT_H
#define CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_FILE_CONTENT_H

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#ifndef MAP_POPULATE
#define MAP_POPULATE 0
#endif
#define FS_DEMO_HAS_MMAP 1
#else
#define FS_DEMO_HAS_MMAP 0
#endif

namespace fs_app {

/// Bad input: `what()` is one line, "<file>: <reason>" or "<file>:<line>: <reason>".
class Input_error : public std::runtime_error { public: using std::runtime_error::runtime_error; };

namespace internal {

/// Refuses, with its own message, a path that is missing, a directory or not a regular
/// file (a FIFO, socket or device): what `File_content` and the programs' other file
/// readers check before opening.
inline void check_regular_file(const std::string& path)
{
  namespace sfs = std::filesystem;
  std::error_code ec;
  const sfs::file_status st = sfs::status(path, ec);
  if(!sfs::exists(st))
    throw Input_error(path + ": no such file");
  if(sfs::is_directory(st))
    throw Input_error(path + ": is a directory, not a mesh file");
  if(!sfs::is_regular_file(st))
    throw Input_error(path + ": is not a regular file (a FIFO, socket or device cannot be read)");
}

/// The whole content of a regular file, mapped into memory read-only (POSIX) or read
/// into a buffer (elsewhere). Anything else (missing, a directory, a FIFO, a device, no
/// read permission) is refused before a byte is read.
class File_content
{
public:
  explicit File_content(const std::string& path)
  {
    check_regular_file(path);
#if FS_DEMO_HAS_MMAP
    const int fd = ::open(path.c_str(), O_RDONLY);
    if(fd < 0)
      throw Input_error(path + ": cannot be opened for reading (" + std::strerror(errno) + ")");
    struct stat info;
    if(::fstat(fd, &info) != 0)
    {
      const int error = errno;
      ::close(fd);
      throw Input_error(path + ": cannot be read (" + std::strerror(error) + ")");
    }
    m_size = static_cast<std::size_t>(info.st_size);
    if(m_size > 0)
    {
      void* map = ::mmap(nullptr, m_size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
      if(map == MAP_FAILED)
      {
        const int error = errno;
        ::close(fd);
        throw Input_error(path + ": cannot be read (" + std::strerror(error) + ")");
      }
      m_data = static_cast<const char*>(map);
    }
    ::close(fd);
#else
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if(file == nullptr)
      throw Input_error(path + ": cannot be opened for reading (" + std::strerror(errno) + ")");
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    try
    {
      m_buffer.resize(ec ? 0 : static_cast<std::size_t>(size));
    }
    catch(const std::exception&)
    {
      std::fclose(file);
      throw Input_error(path + ": is too large to be read into memory");
    }
    const std::size_t got = m_buffer.empty() ? 0 : std::fread(&m_buffer[0], 1, m_buffer.size(), file);
    const bool failed = std::ferror(file) != 0;
    std::fclose(file);
    if(failed || got != m_buffer.size())
      throw Input_error(path + ": cannot be read (an I/O error after " + std::to_string(got) + " bytes)");
    m_data = m_buffer.data();
    m_size = m_buffer.size();
#endif
    if(m_size == 0)
      throw Input_error(path + ": the file is empty");
  }

  /// A view of `size` bytes at `data`, which the caller keeps alive (for readers of
  /// content already in memory, as the fuzzing targets have it).
  File_content(const char* data, std::size_t size) : m_data(data), m_size(size), m_owns(false) {}

  ~File_content()
  {
#if FS_DEMO_HAS_MMAP
    if(m_owns && m_data != nullptr)
      ::munmap(const_cast<char*>(m_data), m_size);
#endif
  }
  File_content(const File_content&) = delete;
  File_content& operator=(const File_content&) = delete;

  const char* data() const { return m_data; }
  std::size_t size() const { return m_size; }
  std::string_view view() const { return std::string_view(m_data, m_size); }

private:
  const char* m_data = nullptr;
  std::size_t m_size = 0;
  bool m_owns = true;
#if !FS_DEMO_HAS_MMAP
  std::string m_buffer;
#endif
};

} // namespace internal
} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_FILE_CONTENT_H
