// SPDX-License-Identifier: GPL-3.0-or-later
// The polygon soup that the programs' file readers produce, the file buffer they read
// from and the text cursor they share. A reader is given the whole file in memory, checks
// every count of a header against the bytes that are really there before it allocates,
// and stops at the first problem with one `Input_error` naming the file and the line
// ("<file>:<line>: <reason>"), so that a malformed file costs bounded time and memory.
// Numbers are parsed with `std::from_chars`; no locale, no stream, no copy of a line.

#ifndef CGAL_FEATURE_SEGMENTATION_DEMO_MESH_IO_MESH_SOUP_H
#define CGAL_FEATURE_SEGMENTATION_DEMO_MESH_IO_MESH_SOUP_H

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <CGAL/assertions.h>

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

namespace fs_demo {

/// Bad input: `what()` is one line, "<file>: <reason>" or "<file>:<line>: <reason>".
class Input_error : public std::runtime_error
{
public:
  explicit Input_error(const std::string& what) : std::runtime_error(what) {}
};

/// A polygon soup exactly as in the file: points and faces in file order. Face `f` uses
/// the points `indices[begin[f]] ... indices[begin[f + 1] - 1]`. Every index is below
/// `points.size()` and every coordinate is finite (the readers check both).
struct Mesh_soup
{
  std::vector<std::array<double, 3> > points;
  std::vector<std::uint32_t> begin{0};   ///< one more entry than there are faces
  std::vector<std::uint32_t> indices;
  std::vector<std::uint32_t> face_line;  ///< line of each face in a text file, else empty
  std::string format;                    ///< "off", "obj", "ply" or "stl"

  std::size_t number_of_faces() const { return begin.size() - 1; }
  std::size_t face_size(std::size_t f) const { return begin[f + 1] - begin[f]; }
  const std::uint32_t* face(std::size_t f) const { return indices.data() + begin[f]; }
};

namespace internal {

// Element counts are stored in 32 bits: a file with more than 4 billion points or
// indices would need tens of gigabytes, far beyond what the pipeline handles anyway.
constexpr std::size_t max_soup_count = std::numeric_limits<std::uint32_t>::max() - 1;

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

/// A token of the file as it may appear in a message: at most 40 characters, anything
/// unprintable shown as '?'.
inline std::string quoted(std::string_view token)
{
  std::string out = "'";
  for(std::size_t i = 0; i < token.size() && i < 40; ++i)
  {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    out += (c >= 32 && c < 127) ? static_cast<char>(c) : '?';
  }
  if(token.size() > 40)
    out += "...";
  return out + "'";
}

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' || c == '\0'; }

// The characters of `token` after an optional leading '+' (from_chars takes no '+').
inline std::pair<const char*, const char*> without_plus(std::string_view token)
{
  const char* first = token.data();
  const char* last = first + token.size();
  if(first != last && *first == '+')
    ++first;
  return {first, last};
}

/// Floating-point number in `token` (a leading '+' allowed); `false` if it is not one.
/// "nan" and "inf" are numbers here: the caller rejects them with a better message.
inline bool parse_double(std::string_view token, double& value)
{
  const auto [first, last] = without_plus(token);
  if(first == last)
    return false;
  const std::from_chars_result r = std::from_chars(first, last, value);
  if(r.ec == std::errc::result_out_of_range)
  {
    value = (*first == '-') ? -HUGE_VAL : HUGE_VAL; // overflow: reported as infinite
    return r.ptr == last;
  }
  return r.ec == std::errc() && r.ptr == last;
}

/// Integer in `token` (a leading '+' allowed); `false` if it is not one or overflows.
inline bool parse_integer(std::string_view token, long long& value)
{
  const auto [first, last] = without_plus(token);
  if(first == last)
    return false;
  const std::from_chars_result r = std::from_chars(first, last, value);
  return r.ec == std::errc() && r.ptr == last;
}

/// Walks a text buffer word by word and line by line, counting lines for messages.
/// A word is a run of bytes that are neither blanks nor line ends; `comment` (if not
/// '\0') starts a comment that runs to the end of the line.
class Text_cursor
{
public:
  Text_cursor(const std::string& path, const char* first, const char* last, char comment,
              std::size_t first_line = 1)
    : m_path(&path), m_p(first), m_end(last), m_class(byte_classes(comment)), m_line(first_line)
  {}

  std::size_t line() const { return m_line; }
  const char* position() const { return m_p; }
  bool at_end() const { return m_p == m_end; }
  std::size_t bytes_left() const { return static_cast<std::size_t>(m_end - m_p); }

  /// `true` if nothing but blanks and a comment remain on the current line.
  bool at_line_end()
  {
    while(m_p != m_end && kind(*m_p) == 1)
      ++m_p;
    if(m_p != m_end && kind(*m_p) == 3)
      while(m_p != m_end && *m_p != '\n')
        ++m_p;
    return m_p == m_end || *m_p == '\n';
  }

  /// Moves to the start of the next line, dropping what is left of this one.
  void next_line()
  {
    const void* nl = std::memchr(m_p, '\n', bytes_left());
    if(nl == nullptr)
      m_p = m_end;
    else
    {
      m_p = static_cast<const char*>(nl) + 1;
      ++m_line;
    }
  }

  /// Skips empty and comment-only lines; `false` at the end of the file.
  bool skip_empty_lines()
  {
    while(at_line_end())
    {
      if(m_p == m_end)
        return false;
      next_line();
    }
    return true;
  }

  /// The next word of the current line, empty at the end of the line.
  std::string_view word()
  {
    if(at_line_end())
      return std::string_view();
    const char* start = m_p;
    while(m_p != m_end && kind(*m_p) == 0)
      ++m_p;
    return std::string_view(start, static_cast<std::size_t>(m_p - start));
  }

  /// The next word, on this line or a later one (empty only at the end of the file).
  std::string_view word_across_lines()
  {
    if(!skip_empty_lines())
      return std::string_view();
    return word();
  }

  /// Throws the `Input_error` "<file>:<line>: <reason>".
  [[noreturn]] void fail(const std::string& reason) const
  {
    throw Input_error(*m_path + ":" + std::to_string(m_line) + ": " + reason);
  }

  /// The next word as a finite coordinate; `what` names it in messages. Plain decimals
  /// of up to 15 significant digits and exponents up to 22, which are most numbers in
  /// mesh files, are converted exactly on the spot (Clinger's fast path: the digits and
  /// the power of ten are both exact doubles, so one multiplication or division rounds
  /// correctly); anything else goes to `std::from_chars`.
  double coordinate(const char* what)
  {
    double fast;
    if(fast_decimal(fast))
      return fast;
    const std::string_view w = word();
    if(w.empty())
      fail(std::string("expected ") + what + ", found the end of the line");
    double value;
    if(!parse_double(w, value))
      fail(std::string("expected ") + what + ", found " + quoted(w));
    if(!std::isfinite(value))
      fail(std::string("has a NaN or infinite coordinate (") + quoted(w) + ")");
    return value;
  }

  /// The next word (on this line, or on any line if `across_lines`) as an integer in
  /// [0, max]; `what` names it in messages.
  std::size_t count(const char* what, std::size_t max, bool across_lines = false)
  {
    const std::string_view w = across_lines ? word_across_lines() : word();
    if(w.empty())
      fail(std::string("expected ") + what + ", found the end of " +
           (across_lines ? "the file" : "the line"));
    long long value;
    if(!parse_integer(w, value) || value < 0)
      fail(std::string("expected ") + what + " (an integer >= 0), found " + quoted(w));
    if(static_cast<unsigned long long>(value) > max)
      fail(std::string(what) + " " + std::string(w) + " is too large (at most " +
           std::to_string(max) + " for this file)");
    return static_cast<std::size_t>(value);
  }

  /// The next word as a non-negative integer, or -1 if it is not one (or has more than
  /// 18 digits); the cursor is left after the word either way.
  long long index()
  {
    if(at_line_end())
      return -1;
    const char* p = m_p;
    if(*p == '+')
      ++p;
    const char* const start = p;
    long long value = 0;
    while(p != m_end && *p >= '0' && *p <= '9' && p - start < 18)
      value = value * 10 + (*p++ - '0');
    const bool ok = p != start && (p == m_end || kind(*p) != 0);
    m_p = p;
    if(!ok)
      word(); // the rest of the word
    return ok ? value : -1;
  }

private:
  int kind(char c) const { return m_class[static_cast<unsigned char>(c)]; }

  bool fast_decimal(double& value)
  {
    if(at_line_end())
      return false;
    const char* p = m_p;
    bool negative = false;
    if(*p == '-' || *p == '+')
      negative = *p++ == '-';
    std::uint64_t digits = 0;
    int count = 0, exponent = 0;
    const char* const start = p;
    while(p != m_end && *p >= '0' && *p <= '9')
    {
      if(digits != 0 || *p != '0')
        ++count;
      digits = digits * 10 + std::uint64_t(*p++ - '0');
      if(count > 15)
        return false;
    }
    bool any = p != start;
    if(p != m_end && *p == '.')
    {
      const char* fraction = ++p;
      while(p != m_end && *p >= '0' && *p <= '9')
      {
        if(digits != 0 || *p != '0')
          ++count;
        digits = digits * 10 + std::uint64_t(*p++ - '0');
        --exponent;
        if(count > 15)
          return false;
      }
      any = any || p != fraction;
    }
    if(!any)
      return false;
    if(p != m_end && (*p == 'e' || *p == 'E'))
    {
      ++p;
      bool negative_exponent = false;
      if(p != m_end && (*p == '-' || *p == '+'))
        negative_exponent = *p++ == '-';
      const char* exponent_start = p;
      int e = 0;
      while(p != m_end && *p >= '0' && *p <= '9' && e < 1000)
        e = e * 10 + (*p++ - '0');
      if(p == exponent_start)
        return false;
      exponent += negative_exponent ? -e : e;
    }
    if(p != m_end && kind(*p) == 0)
      return false;
    if(exponent < -22 || exponent > 22)
      return false;
    static const double powers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                    1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                    1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    double v = static_cast<double>(digits);
    v = exponent < 0 ? v / powers[-exponent] : v * powers[exponent];
    value = negative ? -v : v;
    m_p = p;
    return true;
  }

  const std::string* m_path;
  const char* m_p;
  const char* m_end;
  const unsigned char* m_class;

  // What each byte is: a word byte (0), a blank (1), the end of a line (2) or the start
  // of a comment (3); one table lookup per byte in the loops above. Only '#' and no
  // comment at all are used.
  static const unsigned char* byte_classes(char comment)
  {
    struct Table
    {
      unsigned char c[256];
      explicit Table(char comment)
      {
        for(int i = 0; i < 256; ++i)
          c[i] = is_blank(static_cast<char>(i)) ? 1 : 0;
        c[static_cast<unsigned char>('\n')] = 2;
        if(comment != '\0')
          c[static_cast<unsigned char>(comment)] = 3;
      }
    };
    static const Table none('\0'), hash('#');
    CGAL_assertion(comment == '\0' || comment == '#');
    return comment == '#' ? hash.c : none.c;
  }

  std::size_t m_line;
};

/// Exact merging of points at the same position, over the points of a soup: an open
/// addressing table of point indices (no allocation per point), keyed by the bits of
/// the coordinates with -0 taken as 0. Coordinates are finite. Used by the STL reader
/// (points merged as they are read) and by the repairs (points of any file).
class Position_table
{
public:
  explicit Position_table(const std::vector<std::array<double, 3> >& points,
                          std::size_t expected = 0)
    : m_points(&points)
  {
    std::size_t size = 16;
    while(size < 2 * expected)
      size *= 2;
    m_slots.assign(size, empty);
  }

  /// The first point, among those given to this function so far, at the position of
  /// point `i`; `i` itself (now recorded) if there is none.
  std::uint32_t first(std::uint32_t i)
  {
    if(2 * (m_used + 1) > m_slots.size())
      grow();
    const std::array<double, 3>& p = (*m_points)[i];
    for(std::size_t slot = hash(p) & (m_slots.size() - 1);; slot = (slot + 1) & (m_slots.size() - 1))
    {
      const std::uint32_t j = m_slots[slot];
      if(j == empty)
      {
        m_slots[slot] = i;
        ++m_used;
        return i;
      }
      const std::array<double, 3>& q = (*m_points)[j];
      if(p[0] == q[0] && p[1] == q[1] && p[2] == q[2])
        return j;
    }
  }

private:
  static constexpr std::uint32_t empty = std::uint32_t(-1);

  static std::uint64_t hash(const std::array<double, 3>& p)
  {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for(double v : p)
    {
      if(v == 0)
        v = 0; // -0 and 0 are one position
      std::uint64_t b;
      std::memcpy(&b, &v, sizeof b);
      h = (h ^ b) * 0xbf58476d1ce4e5b9ull;
      h ^= h >> 29;
    }
    return h;
  }

  void grow()
  {
    std::vector<std::uint32_t> old(2 * m_slots.size(), empty);
    old.swap(m_slots);
    for(const std::uint32_t j : old)
      if(j != empty)
        for(std::size_t slot = hash((*m_points)[j]) & (m_slots.size() - 1);;
            slot = (slot + 1) & (m_slots.size() - 1))
          if(m_slots[slot] == empty)
          {
            m_slots[slot] = j;
            break;
          }
  }

  const std::vector<std::array<double, 3> >* m_points;
  std::vector<std::uint32_t> m_slots;
  std::size_t m_used = 0;
};

/// Appends the point (x, y, z) to `soup`.
inline void add_point(Mesh_soup& soup, double x, double y, double z)
{
  soup.points.push_back({{x, y, z}});
}

/// Closes the face whose indices were appended since the last call.
inline void end_face(Mesh_soup& soup, std::size_t line)
{
  soup.begin.push_back(static_cast<std::uint32_t>(soup.indices.size()));
  if(line != 0)
    soup.face_line.push_back(static_cast<std::uint32_t>(line));
}

/// The name of face `f` in messages: "face 12", with its line in a text file.
inline std::string face_name(const Mesh_soup& soup, std::size_t f)
{
  std::string name = "face " + std::to_string(f);
  if(f < soup.face_line.size())
    name += " (line " + std::to_string(soup.face_line[f]) + ")";
  return name;
}

} // namespace internal
} // namespace fs_demo

#endif // CGAL_FEATURE_SEGMENTATION_DEMO_MESH_IO_MESH_SOUP_H
