// SPDX-License-Identifier: GPL-3.0-or-later
// The text cursor that the programs' text file readers share (Text_cursor), and the
// parsing of the words it reads. Numbers are parsed with `std::from_chars`; no locale,
// no stream, no copy of a line.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_TEXT_CURSOR_H
#define CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_TEXT_CURSOR_H

#include "file_content.h"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

#include <CGAL/assertions.h>

namespace fs_app {
namespace internal {

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

} // namespace internal
} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_MESH_IO_TEXT_CURSOR_H
