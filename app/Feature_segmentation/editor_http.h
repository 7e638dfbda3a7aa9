// SPDX-License-Identifier: GPL-3.0-or-later
// The HTTP side of the interactive editor, apart from the network: who may use it
// (Editor_access: the session token, the host names, the port), the page's files read
// into memory, and the answer to one request (answer_request): the checks of its
// headers (Host, Origin, token, content type) and the route to Editor_session
// (editor_api.h). editor_server.h runs it on Boost.Beast.

#ifndef CGAL_FEATURE_SEGMENTATION_APP_EDITOR_HTTP_H
#define CGAL_FEATURE_SEGMENTATION_APP_EDITOR_HTTP_H

#include "editor_api.h"
#include "option_table.h"

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace fs_app {

/// The largest request body the editor reads (a stroke over a million faces fits).
constexpr std::size_t editor_max_body_bytes = 8u << 20;

/// Who may use the editor: the session token (empty: none is asked, `--no-token`), the
/// host names the server answers to, and its port (known once it is bound).
struct Editor_access
{
  std::string token;
  std::vector<std::string> hosts = {"localhost", "127.0.0.1", "[::1]"};
  int port = 0;

  /// A Host header naming this server: one of `hosts`, at `port` or without a port.
  bool is_allowed_host(const std::string& header) const
  {
    std::string host = header;
    std::transform(host.begin(), host.end(), host.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    const std::size_t colon = host.rfind(':');
    if(colon != std::string::npos && host.find(']', colon) == std::string::npos)
    {
      if(host.substr(colon + 1) != std::to_string(port)) return false;
      host.erase(colon);
    }
    return std::find(hosts.begin(), hosts.end(), host) != hosts.end();
  }
  /// An Origin header of this server's pages: http://HOST:PORT with an allowed HOST.
  bool is_allowed_origin(const std::string& origin) const
  {
    const std::string scheme = "http://";
    return origin.rfind(scheme, 0) == 0 && origin.find(':', scheme.size()) != std::string::npos &&
           origin.find('/', scheme.size()) == std::string::npos && is_allowed_host(origin.substr(scheme.size()));
  }
  /// Whether a request with these X-Editor-Token and Cookie headers carries the token
  /// (the header, or the cookie fs_editor_token).
  bool has_token(std::string_view token_header, std::string_view cookie_header) const
  {
    if(token.empty()) return true;
    if(same(token_header, token)) return true;
    while(!cookie_header.empty())
    {
      const std::size_t end = std::min(cookie_header.find(';'), cookie_header.size());
      std::string_view cookie = cookie_header.substr(0, end);
      cookie_header.remove_prefix(std::min(end + 1, cookie_header.size()));
      while(!cookie.empty() && cookie.front() == ' ') cookie.remove_prefix(1);
      const std::string_view name = "fs_editor_token=";
      if(cookie.substr(0, name.size()) == name && same(cookie.substr(name.size()), token)) return true;
    }
    return false;
  }

private:
  // compares in a time that does not depend on where the two differ
  static bool same(std::string_view a, std::string_view b)
  {
    if(a.size() != b.size()) return false;
    unsigned char d = 0;
    for(std::size_t i = 0; i < a.size(); ++i) d |= static_cast<unsigned char>(a[i] ^ b[i]);
    return d == 0;
  }
};

/// A random session token: 128 bits from the system's random source, in hexadecimal.
inline std::string random_editor_token()
{
  std::random_device source; // /dev/urandom on Linux
  std::ostringstream text;
  for(int i = 0; i < 4; ++i)
  {
    const std::uint32_t x = source();
    const char* digits = "0123456789abcdef";
    for(int k = 28; k >= 0; k -= 4) text << digits[(x >> k) & 15u];
  }
  return text.str();
}


namespace internal {

namespace beast = boost::beast;
namespace http = boost::beast::http;
namespace net = boost::asio;
using tcp = boost::asio::ip::tcp;

/// The limits that keep slow and large requests from taking the server.
struct Editor_server_limits
{
  std::chrono::seconds header_time{10}; // the headers, from the connection's turn to speak
  std::chrono::seconds body_time{30};   // the body, once the headers are in
  std::chrono::seconds write_time{30};  // an answer
  std::size_t header_bytes = 16 * 1024;
  std::size_t body_bytes = editor_max_body_bytes;
  int connections = 512; // open at once; more are closed as they arrive
};

// The folder of the editor's page: --web-root, else the one built next to the program
// (FS_EDITOR_WEB_DIR), else share/feature_segmentation/editor beside an installed one.
inline std::filesystem::path editor_web_root(const Options& options)
{
  namespace sfs = std::filesystem;
  std::vector<sfs::path> candidates;
  if(!options.web_root.empty())
    candidates.push_back(options.web_root);
  else
  {
#ifdef FS_EDITOR_WEB_DIR
    candidates.push_back(FS_EDITOR_WEB_DIR);
#endif
    std::error_code ec;
    const sfs::path exe = sfs::read_symlink("/proc/self/exe", ec);
    if(!ec) candidates.push_back(exe.parent_path().parent_path() / "share" / "feature_segmentation" / "editor");
  }
  for(const sfs::path& p : candidates)
    if(sfs::is_regular_file(p / "index.html") && sfs::is_regular_file(p / "three.module.min.js"))
      return p;
  std::string tried;
  for(const sfs::path& p : candidates) tried += (tried.empty() ? "" : ", ") + p.string();
  throw std::runtime_error("the editor's web page is not found (looked in " + tried +
                           "; build the program with npm available, or pass --web-root DIR)");
}

/// A file of the page: its bytes and MIME type.
struct Page_file
{
  std::string content;
  std::string type;
};

/// The regular files directly in `folder`, by name ("/" is index.html): the page is served
/// from memory, so no request names a file outside it.
inline std::map<std::string, Page_file> read_editor_page(const std::filesystem::path& folder)
{
  const std::map<std::string, std::string> types = {
    {".html", "text/html; charset=utf-8"}, {".js", "text/javascript; charset=utf-8"},
    {".css", "text/css; charset=utf-8"},   {".txt", "text/plain; charset=utf-8"},
    {".json", "application/json"},         {".svg", "image/svg+xml"},
    {".png", "image/png"}};
  std::map<std::string, Page_file> page;
  for(const auto& entry : std::filesystem::directory_iterator(folder))
  {
    if(!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if(!in) throw std::runtime_error(entry.path().string() + ": cannot read this file of the editor's page");
    const auto type = types.find(entry.path().extension().string());
    page["/" + entry.path().filename().string()] =
      Page_file{bytes.str(), type == types.end() ? "application/octet-stream" : type->second};
  }
  page["/"] = page.at("/index.html");
  return page;
}

/// An answer: status, body and type; `close` ends the connection after it.
struct Http_answer
{
  http::status status = http::status::ok;
  std::string body;
  std::string type = "application/json";
  bool close = false;
};

inline Http_answer json_answer(std::string body, http::status status = http::status::ok)
{
  return Http_answer{status, std::move(body), "application/json", false};
}

inline Http_answer error_answer(http::status status, const std::string& what, bool close = false)
{
  // a message may quote the request: invalid UTF-8 in it is replaced, not an error
  return Http_answer{status, nlohmann::json{{"error", what}}.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                     "application/json", close};
}

/// The parameters of a query string `a=1&b=2`, percent-decoded; nothing if an escape is malformed.
inline std::optional<std::map<std::string, std::string>> parse_query(std::string_view query)
{
  const auto decode = [](std::string_view text) -> std::optional<std::string> {
    std::string out;
    for(std::size_t i = 0; i < text.size(); ++i)
    {
      if(text[i] == '+') { out += ' '; continue; }
      if(text[i] != '%') { out += text[i]; continue; }
      if(i + 2 >= text.size() || !std::isxdigit(static_cast<unsigned char>(text[i + 1])) ||
         !std::isxdigit(static_cast<unsigned char>(text[i + 2])))
        return std::nullopt;
      out += static_cast<char>(std::stoi(std::string(text.substr(i + 1, 2)), nullptr, 16));
      i += 2;
    }
    return out;
  };
  std::map<std::string, std::string> parameters;
  while(!query.empty())
  {
    const std::size_t end = std::min(query.find('&'), query.size());
    const std::string_view item = query.substr(0, end);
    query.remove_prefix(std::min(end + 1, query.size()));
    if(item.empty()) continue;
    const std::size_t eq = std::min(item.find('='), item.size());
    const auto key = decode(item.substr(0, eq));
    const auto value = decode(item.substr(std::min(eq + 1, item.size())));
    if(!key || !value) return std::nullopt;
    parameters[*key] = *value;
  }
  return parameters;
}

/// The refusal of a request that its headers alone condemn (Host, token, Origin, content
/// type), checked before its body is read; nothing if it may go on. (The parser refuses a
/// Content-Length over the limit.)
inline std::optional<Http_answer> refuse_by_headers(const http::request_header<>& h, const Editor_access& access)
{
  const auto quoted = [](beast::string_view v) { return "'" + std::string(v.substr(0, 100)) + "'"; };
  if(!access.is_allowed_host(std::string(h[http::field::host])))
    return error_answer(http::status::forbidden, "the Host header " + quoted(h[http::field::host]) +
                                                   " does not name this editor (open the address the program printed)", true);
  const std::string_view target(h.target().data(), h.target().size());
  if(target.rfind("/api/", 0) != 0) return std::nullopt; // the page's files
  if(!access.has_token(std::string_view(h["X-Editor-Token"].data(), h["X-Editor-Token"].size()),
                       std::string_view(h[http::field::cookie].data(), h[http::field::cookie].size())))
    return error_answer(http::status::forbidden,
                        "missing or wrong session token: open the address the program printed (it ends with ?token=...)", true);
  if(h.method() == http::verb::post)
  {
    if(h.find(http::field::origin) != h.end() && !access.is_allowed_origin(std::string(h[http::field::origin])))
      return error_answer(http::status::forbidden, "requests from the page at " + quoted(h[http::field::origin]) +
                                                     " are not accepted", true);
    const beast::string_view type = h[http::field::content_type];
    if(type.substr(0, 16) != "application/json")
      return error_answer(http::status::unsupported_media_type,
                          "a POST must have Content-Type: application/json (got " + quoted(type) + ")", true);
  }
  return std::nullopt;
}

// Parses the body as JSON and answers with `call(body)` (JSON, or the bytes `call`
// returns as `type`); 400 for bad JSON or a request that `call` refuses.
template <typename Call>
Http_answer answer_json_request(const std::string& body, Call call, const char* type = "application/json")
{
  nlohmann::json request;
  try
  {
    request = nlohmann::json::parse(body);
  }
  catch(const nlohmann::json::exception& e)
  {
    return error_answer(http::status::bad_request, std::string("the request is not valid JSON: ") + e.what());
  }
  try
  {
    if constexpr(std::is_same<decltype(call(request)), std::string>::value)
      return Http_answer{http::status::ok, call(request), type, false};
    else
      return json_answer(call(request).dump());
  }
  catch(const Request_error& e)
  {
    return error_answer(http::status::bad_request, e.what());
  }
}

/// The answer to a whole request that passed refuse_by_headers (run on a worker thread).
inline Http_answer answer_request(const http::request<http::string_body>& req, Editor_session& session,
                                  const std::map<std::string, Page_file>& page)
{
  const std::string target(req.target());
  const std::size_t question = target.find('?');
  const std::string path = target.substr(0, question);
  const auto query = parse_query(question == std::string::npos ? std::string_view() : std::string_view(target).substr(question + 1));
  if(!query) return error_answer(http::status::bad_request, "a malformed %-escape in the query string");
  const bool get = req.method() == http::verb::get, post = req.method() == http::verb::post;
  const auto wrong_method = [&](const char* allowed) {
    return error_answer(http::status::method_not_allowed, path + " accepts " + allowed + " only");
  };
  try
  {
    if(path.rfind("/api/", 0) != 0)
    {
      const auto file = page.find(path);
      if(file == page.end()) return error_answer(http::status::not_found, "no such resource");
      if(!get) return wrong_method("GET");
      return Http_answer{http::status::ok, file->second.content, file->second.type, false};
    }
    if(path == "/api/state" || path == "/api/mesh" || path == "/api/labels" || path == "/api/features" ||
       path == "/api/boundaries" || path == "/api/history")
    {
      if(!get) return wrong_method("GET");
      if(path == "/api/state") return json_answer(session.state().dump());
      if(path == "/api/mesh" || path == "/api/labels")
      {
        const auto format = query->find("format");
        const std::string value = format == query->end() ? "json" : format->second;
        const bool mesh = path == "/api/mesh";
        if(value == "runs" && !mesh)
        {
          if(query->find("vertices") != query->end())
            return error_answer(http::status::bad_request, "'vertices' is 0 or 1, on labels?format=binary only");
          return Http_answer{http::status::ok, session.labels_runs(), "application/octet-stream", false};
        }
        if(value != "json" && value != "binary")
          return error_answer(http::status::bad_request, path.substr(5) + ": 'format' must be json or binary" +
                                                         (mesh ? "" : " or runs"));
        const auto vertices = query->find("vertices");
        if(vertices != query->end() && (mesh || value != "binary" || (vertices->second != "0" && vertices->second != "1")))
          return error_answer(http::status::bad_request, "'vertices' is 0 or 1, on labels?format=binary only");
        if(value == "json") return json_answer(mesh ? session.mesh() : session.labels());
        const bool with_vertices = vertices == query->end() || vertices->second == "1";
        return Http_answer{http::status::ok, mesh ? session.mesh_binary() : session.labels_binary(with_vertices),
                           "application/octet-stream", false};
      }
      if(path == "/api/features") return json_answer(session.features());
      if(path == "/api/boundaries")
      {
        const auto smooth = query->find("smooth");
        const std::string value = smooth == query->end() ? "1" : smooth->second;
        if(value != "0" && value != "1") return error_answer(http::status::bad_request, "boundaries: 'smooth' must be 0 or 1");
        return json_answer(session.boundaries(value == "1"));
      }
      std::size_t number[2] = {0, 50};
      const char* names[2] = {"from", "count"};
      for(int k = 0; k < 2; ++k)
      {
        const auto it = query->find(names[k]);
        if(it == query->end()) continue;
        const std::string& text = it->second;
        if(text.empty() || text.size() > 9 || text.find_first_not_of("0123456789") != std::string::npos)
          return error_answer(http::status::bad_request, std::string("history: '") + names[k] + "' must be an integer >= 0");
        number[k] = std::stoul(text);
      }
      return json_answer(session.history(number[0], number[1]).dump());
    }
    if(path == "/api/edit" || path == "/api/restart" || path == "/api/save")
    {
      if(!post) return wrong_method("POST");
      if(path == "/api/edit")
      {
        const auto labels = query->find("labels");
        if(labels != query->end() && labels->second != "binary" && labels->second != "runs")
          return error_answer(http::status::bad_request, "edit: 'labels' must be binary or runs");
        if(labels == query->end())
          return answer_json_request(req.body(), [&](const nlohmann::json& j) { return session.edit(j); });
        const bool runs = labels->second == "runs";
        return answer_json_request(req.body(), [&](const nlohmann::json& j) { return session.edit_with_labels(j, runs); },
                                   "application/octet-stream");
      }
      if(path == "/api/restart")
        return answer_json_request(req.body(), [&](const nlohmann::json& j) { return session.restart(j); });
      return json_answer(session.save().dump());
    }
    return error_answer(http::status::not_found, "no such resource");
  }
  catch(const Request_error& e)
  {
    return error_answer(http::status::bad_request, e.what());
  }
  catch(const std::bad_alloc&)
  {
    return error_answer(http::status::internal_server_error, "out of memory");
  }
  catch(const std::exception& e)
  {
    return error_answer(http::status::internal_server_error, e.what());
  }
}

} // namespace internal
} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_APP_EDITOR_HTTP_H
