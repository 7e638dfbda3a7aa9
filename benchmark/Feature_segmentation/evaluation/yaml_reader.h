// SPDX-License-Identifier: GPL-3.0-or-later
// A small reader for the subset of YAML that datasets of CAD models use for their
// annotations (the ABC dataset's feature files, NH-Rep's copies of them): block
// mappings and sequences by indentation, flow collections ([...], {...}) spanning lines,
// plain, single- and double-quoted scalars, comments and a leading "---". Anchors,
// aliases, tags and block scalars (| and >) are rejected with a message, not misread.
// It keeps the evaluation free of a YAML library, so the ctest floor on the ABC model
// builds with the package's own dependencies.

#ifndef CGAL_FEATURE_SEGMENTATION_BENCHMARK_YAML_READER_H
#define CGAL_FEATURE_SEGMENTATION_BENCHMARK_YAML_READER_H

#include <cstddef>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fs_evaluation {

/// A YAML node: a scalar (kept as text), a sequence or a mapping (in file order).
struct Yaml_node
{
  enum Kind { SCALAR, SEQUENCE, MAPPING };
  Kind kind = SCALAR;
  std::string scalar;
  std::vector<Yaml_node> items;
  std::vector<std::pair<std::string, Yaml_node> > entries;

  /// The value of `key` in a mapping, or nullptr.
  const Yaml_node* find(const std::string& key) const
  {
    for(const auto& e : entries)
      if(e.first == key) return &e.second;
    return nullptr;
  }
};

/// Thrown on text outside the supported subset or malformed YAML; says the line.
struct Yaml_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

class Yaml_parser
{
public:
  explicit Yaml_parser(std::string text) : m_text(std::move(text)) {}

  Yaml_node parse()
  {
    skip_blank_lines();
    if(m_text.compare(m_pos, 3, "---") == 0 && (m_pos + 3 == m_text.size() || is_space_or_eol(m_text[m_pos + 3])))
    {
      m_pos += 3;
      skip_blank_lines();
    }
    if(at_end()) return Yaml_node();
    Yaml_node root = parse_block(column());
    skip_blank_lines();
    if(!at_end()) fail("unexpected content");
    return root;
  }

private:
  std::string m_text;
  std::size_t m_pos = 0;

  bool at_end() const { return m_pos >= m_text.size(); }
  char peek(std::size_t k = 0) const { return m_pos + k < m_text.size() ? m_text[m_pos + k] : '\0'; }
  static bool is_space_or_eol(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\0'; }

  std::size_t line_number() const
  {
    std::size_t n = 1;
    for(std::size_t i = 0; i < m_pos && i < m_text.size(); ++i) n += (m_text[i] == '\n');
    return n;
  }
  [[noreturn]] void fail(const std::string& what) const
  {
    throw Yaml_error("YAML line " + std::to_string(line_number()) + ": " + what);
  }
  std::size_t column() const
  {
    std::size_t start = m_text.rfind('\n', m_pos == 0 ? 0 : m_pos - 1);
    start = (start == std::string::npos || (m_pos == 0)) ? 0 : start + 1;
    return m_pos - start;
  }
  void skip_spaces() { while(peek() == ' ' || peek() == '\t') ++m_pos; }
  void skip_comment() { if(peek() == '#') while(!at_end() && peek() != '\n') ++m_pos; }
  // To the first character of the next line holding content (not blank, not a comment).
  void skip_blank_lines()
  {
    while(!at_end())
    {
      const std::size_t save = m_pos;
      skip_spaces();
      skip_comment();
      if(peek() == '\r') ++m_pos;
      if(peek() == '\n') { ++m_pos; continue; }
      if(at_end()) return;
      m_pos = save;
      skip_spaces();
      return;
    }
  }
  // Whitespace, line breaks and comments inside a flow collection.
  void skip_flow_space()
  {
    while(!at_end())
    {
      char c = peek();
      if(c == ' ' || c == '\t' || c == '\r' || c == '\n') ++m_pos;
      else if(c == '#') skip_comment();
      else return;
    }
  }
  // Does the current line (from m_pos) hold "key:" outside quotes and brackets?
  bool line_has_mapping_key() const
  {
    std::size_t i = m_pos;
    if(i < m_text.size() && (m_text[i] == '[' || m_text[i] == '{')) return false;
    char quote = 0;
    for(; i < m_text.size() && m_text[i] != '\n'; ++i)
    {
      const char c = m_text[i];
      if(quote) { if(c == quote) quote = 0; continue; }
      if((c == '"' || c == '\'') && i == m_pos) { quote = c; continue; }
      if(c == '#' && i > m_pos && (m_text[i - 1] == ' ' || m_text[i - 1] == '\t')) return false;
      if(c == ':' && (i + 1 == m_text.size() || is_space_or_eol(m_text[i + 1]))) return true;
    }
    return false;
  }
  void reject_unsupported()
  {
    const char c = peek();
    if(c == '&' || c == '*' || c == '!' || c == '|' || c == '>')
      fail(std::string("unsupported YAML feature '") + c + "' (anchors, aliases, tags, block scalars)");
  }

  Yaml_node parse_block(std::size_t indent)
  {
    reject_unsupported();
    if(peek() == '-' && is_space_or_eol(peek(1))) return parse_block_sequence(indent);
    if(line_has_mapping_key()) return parse_block_mapping(indent);
    return parse_inline_value();
  }

  Yaml_node parse_block_sequence(std::size_t indent)
  {
    Yaml_node node;
    node.kind = Yaml_node::SEQUENCE;
    while(!at_end() && column() == indent && peek() == '-' && is_space_or_eol(peek(1)))
    {
      ++m_pos;
      skip_spaces();
      skip_comment();
      if(peek() == '\n' || peek() == '\r' || at_end())
      {
        skip_blank_lines();
        if(at_end() || column() <= indent) node.items.emplace_back(); // null item
        else node.items.push_back(parse_block(column()));
      }
      else
        node.items.push_back(parse_block(column()));
      skip_blank_lines();
    }
    if(!at_end() && column() > indent) fail("bad indentation in a sequence");
    return node;
  }

  Yaml_node parse_block_mapping(std::size_t indent)
  {
    Yaml_node node;
    node.kind = Yaml_node::MAPPING;
    while(!at_end() && column() == indent && line_has_mapping_key())
    {
      std::string key = (peek() == '"' || peek() == '\'') ? parse_quoted() : parse_plain_key();
      skip_spaces();
      if(peek() != ':') fail("expected ':' after key '" + key + "'");
      ++m_pos;
      skip_spaces();
      skip_comment();
      Yaml_node value;
      if(peek() == '\n' || peek() == '\r' || at_end())
      {
        skip_blank_lines();
        if(!at_end() && (column() > indent || (column() == indent && peek() == '-' && is_space_or_eol(peek(1)))))
          value = parse_block(column());
      }
      else
      {
        value = parse_block(column());
      }
      node.entries.emplace_back(std::move(key), std::move(value));
      skip_blank_lines();
    }
    if(!at_end() && column() > indent) fail("bad indentation in a mapping");
    return node;
  }

  std::string parse_plain_key()
  {
    const std::size_t start = m_pos;
    while(!at_end() && !(peek() == ':' && is_space_or_eol(peek(1))) && peek() != '\n') ++m_pos;
    return trim(m_text.substr(start, m_pos - start));
  }

  // A value that starts on the current line: a flow collection or a scalar.
  Yaml_node parse_inline_value()
  {
    reject_unsupported();
    if(peek() == '[' || peek() == '{') return parse_flow();
    Yaml_node node;
    if(peek() == '"' || peek() == '\'') node.scalar = parse_quoted();
    else
    {
      const std::size_t start = m_pos;
      while(!at_end() && peek() != '\n' && !(peek() == '#' && (m_text[m_pos - 1] == ' ' || m_text[m_pos - 1] == '\t')))
        ++m_pos;
      node.scalar = trim(m_text.substr(start, m_pos - start));
    }
    skip_spaces();
    skip_comment();
    if(!at_end() && peek() != '\n' && peek() != '\r') fail("unexpected text after a value");
    return node;
  }

  Yaml_node parse_flow()
  {
    skip_flow_space();
    reject_unsupported();
    Yaml_node node;
    if(peek() == '[' || peek() == '{')
    {
      const bool seq = (peek() == '[');
      const char close = seq ? ']' : '}';
      node.kind = seq ? Yaml_node::SEQUENCE : Yaml_node::MAPPING;
      ++m_pos;
      skip_flow_space();
      while(peek() != close)
      {
        if(at_end()) fail(std::string("unterminated flow collection, expected '") + close + "'");
        if(seq) node.items.push_back(parse_flow());
        else
        {
          skip_flow_space();
          std::string key = (peek() == '"' || peek() == '\'') ? parse_quoted() : parse_flow_plain(true);
          skip_flow_space();
          Yaml_node value;
          if(peek() == ':')
          {
            ++m_pos;
            value = parse_flow();
          }
          node.entries.emplace_back(std::move(key), std::move(value));
        }
        skip_flow_space();
        if(peek() == ',') { ++m_pos; skip_flow_space(); }
        else if(peek() != close) fail(std::string("expected ',' or '") + close + "' in a flow collection");
      }
      ++m_pos;
      return node;
    }
    if(peek() == '"' || peek() == '\'') node.scalar = parse_quoted();
    else node.scalar = parse_flow_plain(false);
    return node;
  }

  // A plain scalar inside a flow collection: up to ',', ']', '}' or ": ", folded over
  // line breaks.
  std::string parse_flow_plain(bool is_key)
  {
    std::string out;
    while(!at_end())
    {
      const char c = peek();
      if(c == ',' || c == ']' || c == '}' || c == '[' || c == '{') break;
      if(c == ':' && (is_space_or_eol(peek(1)) || peek(1) == ',' || peek(1) == ']' || peek(1) == '}' || is_key)) break;
      if(c == '#' && !out.empty() && (out.back() == ' ')) break;
      if(c == '\n' || c == '\r' || c == '\t') { if(!out.empty() && out.back() != ' ') out += ' '; ++m_pos; continue; }
      out += c;
      ++m_pos;
    }
    return trim(out);
  }

  std::string parse_quoted()
  {
    const char q = peek();
    ++m_pos;
    std::string out;
    while(true)
    {
      if(at_end()) fail("unterminated quoted scalar");
      const char c = peek();
      ++m_pos;
      if(q == '\'' && c == '\'')
      {
        if(peek() == '\'') { out += '\''; ++m_pos; continue; }
        break;
      }
      if(q == '"' && c == '"') break;
      if(q == '"' && c == '\\')
      {
        const char e = peek();
        ++m_pos;
        switch(e)
        {
          case 'n': out += '\n'; break;
          case 't': out += '\t'; break;
          case '"': out += '"'; break;
          case '\\': out += '\\'; break;
          case '/': out += '/'; break;
          default: fail(std::string("unsupported escape \\") + e);
        }
        continue;
      }
      out += c;
    }
    return out;
  }

  static std::string trim(const std::string& s)
  {
    const std::size_t b = s.find_first_not_of(" \t\r\n");
    if(b == std::string::npos) return std::string();
    const std::size_t e = s.find_last_not_of(" \t\r\n");
    return s.substr(b, e - b + 1);
  }
};

/// Reads and parses a YAML file; throws `Yaml_error` (or `std::runtime_error` when the
/// file cannot be read).
inline Yaml_node read_yaml_file(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if(!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream ss;
  ss << in.rdbuf();
  return Yaml_parser(ss.str()).parse();
}

} // namespace fs_evaluation

#endif // CGAL_FEATURE_SEGMENTATION_BENCHMARK_YAML_READER_H
