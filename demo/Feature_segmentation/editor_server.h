// SPDX-License-Identifier: GPL-3.0-or-later
// `feature_segmentation edit MESH`: the interactive editor of the paper (Section 4) as
// a local web page. An event-driven HTTP server (Boost.Beast on one Asio thread, the
// edits on two worker threads) bound to 127.0.0.1 by default serves the page (editor/ in
// the build: HTML, JavaScript and three.js, read into memory at start, nothing fetched at
// run time) and the JSON interface of editor_api.h:
//   GET  /api/state, /api/mesh?format=json|binary, /api/labels?format=json|binary,
//        /api/features, /api/boundaries?smooth=0|1,
//        /api/history?from=K&count=N
//   POST /api/edit   one edit (body: JSON), answered with the new state
//   POST /api/restart  another crest-line scale: {"radius": X, "strength_threshold": T}
//   POST /api/save   writes the outputs and edits.txt into --output-dir
// A refused request gets a 4xx status and {"error": "..."} naming the fault (400 a bad
// request, 403 the token, Host or Origin, 413 a body over 8 MB, chunked or not, 415
// the content type, 431 headers over 16 KB); an unexpected failure 500; the state never
// changes on an error.
// Only the user can drive it: every request must name this server in its Host header
// (localhost, 127.0.0.1, [::1] or --host, at its port: a DNS-rebinding page cannot), every
// API request must carry the session token (random per start, in the address the
// program prints; the page sends it as the X-Editor-Token header and as a cookie), and a
// POST must be application/json (so a cross-site request needs a preflight, which fails)
// from no other Origin. These checks run on the headers, before any body is read.
// Slow clients cost memory, not workers: a request's headers must arrive within 10 s of
// the connection's turn to speak (its opening or its previous answer), its body within
// 30 s more; at most 1024 connections are open at once.

#ifndef CGAL_FEATURE_SEGMENTATION_DEMO_EDITOR_SERVER_H
#define CGAL_FEATURE_SEGMENTATION_DEMO_EDITOR_SERVER_H

#include "editor_api.h"
#include "program_options.h"

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/thread_pool.hpp>
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

// Parses the body as JSON and answers with `call(body)`; 400 for bad JSON or a request
// that `call` refuses.
template <typename Call>
Http_answer answer_json_request(const std::string& body, Call call)
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
        if(value != "json" && value != "binary")
          return error_answer(http::status::bad_request, path.substr(5) + ": 'format' must be json or binary");
        const bool mesh = path == "/api/mesh";
        if(value == "json") return json_answer(mesh ? session.mesh() : session.labels());
        return Http_answer{http::status::ok, mesh ? session.mesh_binary() : session.labels_binary(),
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
        return answer_json_request(req.body(), [&](const nlohmann::json& j) { return session.edit(j); });
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

class Editor_http_server;

// One connection: headers (checked), then the body, then the answer computed on a
// worker, written back; again while the client keeps the connection alive.
class Editor_connection : public std::enable_shared_from_this<Editor_connection>
{
public:
  Editor_connection(tcp::socket socket, Editor_http_server& server, std::atomic<int>& open)
      : m_stream(std::move(socket)), m_server(server), m_open(open)
  {
    ++m_open;
  }
  ~Editor_connection() { --m_open; }
  inline void start() { read_header(); }

private:
  inline void read_header();
  inline void on_header(beast::error_code ec);
  inline void read_body();
  inline void on_body(beast::error_code ec);
  inline void fail(beast::error_code ec);
  inline void write(Http_answer answer, bool keep_alive);
  inline void drain();

  beast::tcp_stream m_stream;
  beast::flat_buffer m_buffer;
  std::optional<http::request_parser<http::string_body>> m_parser;
  http::response<http::string_body> m_response;
  std::array<char, 8 * 1024> m_scratch;
  std::size_t m_discarded = 0;
  Editor_http_server& m_server;
  std::atomic<int>& m_open;
};

/// The editor's HTTP server: one Asio thread for the connections, two workers for the
/// answers (the session lets one edit run at a time).
class Editor_http_server
{
public:
  Editor_http_server(Editor_session& session, std::map<std::string, Page_file> page, const Editor_access& access,
                     Editor_server_limits limits = {})
      : m_session(session), m_page(std::move(page)), m_access(access), m_limits(limits), m_acceptor(m_io),
        m_retry(m_io)
  {}

  /// Listens on `host`:`port` (0: a free port) and answers with the port.
  /// \throws std::runtime_error if it cannot
  int listen(const std::string& host, int port)
  {
    beast::error_code ec;
    tcp::resolver resolver(m_io);
    const auto endpoints = resolver.resolve(host, std::to_string(port), tcp::resolver::passive, ec);
    if(ec || endpoints.empty())
      throw std::runtime_error("cannot listen on " + host + ":" + std::to_string(port) + " (" + ec.message() + ")");
    const tcp::endpoint endpoint = endpoints.begin()->endpoint();
    m_acceptor.open(endpoint.protocol(), ec);
    if(!ec) m_acceptor.set_option(net::socket_base::reuse_address(true), ec);
    if(!ec) m_acceptor.bind(endpoint, ec);
    if(!ec) m_acceptor.listen(net::socket_base::max_listen_connections, ec);
    if(ec)
      throw std::runtime_error("cannot listen on " + host + ":" + std::to_string(port) + " (" + ec.message() +
                               ": in use, or not an address of this machine)");
    return m_acceptor.local_endpoint().port();
  }

  /// Serves until the process is stopped.
  void run()
  {
    accept();
    m_io.run();
  }

  const Editor_server_limits& limits() const { return m_limits; }
  std::optional<Http_answer> refuse(const http::request_header<>& h) const
  {
    return refuse_by_headers(h, m_access);
  }
  /// Computes the answer to `req` on a worker, then calls `done(answer)` on the
  /// connections' thread.
  template <typename Done>
  void answer(http::request<http::string_body> req, Done done)
  {
    net::post(m_workers, [this, req = std::move(req), done = std::move(done)]() mutable {
      Http_answer a = answer_request(req, m_session, m_page);
      net::post(m_io, [a = std::move(a), done = std::move(done)]() mutable { done(std::move(a)); });
    });
  }

private:
  void accept()
  {
    m_acceptor.async_accept(m_io, [this](beast::error_code ec, tcp::socket socket) {
      if(ec)
      {
        // out of file descriptors, most likely: try again shortly rather than spin
        m_retry.expires_after(std::chrono::milliseconds(50));
        m_retry.async_wait([this](beast::error_code) { accept(); });
        return;
      }
      if(m_open.load() < m_limits.connections)
        std::make_shared<Editor_connection>(std::move(socket), *this, m_open)->start();
      accept(); // a socket over the limit is closed as it goes out of scope
    });
  }

  Editor_session& m_session;
  std::map<std::string, Page_file> m_page;
  const Editor_access& m_access;
  Editor_server_limits m_limits;
  net::io_context m_io{1};
  tcp::acceptor m_acceptor;
  net::steady_timer m_retry;
  net::thread_pool m_workers{2};
  std::atomic<int> m_open{0};
};

void Editor_connection::read_header()
{
  m_parser.emplace();
  m_parser->header_limit(static_cast<std::uint32_t>(m_server.limits().header_bytes));
  m_parser->body_limit(m_server.limits().body_bytes); // chunked bodies too
  m_stream.expires_after(m_server.limits().header_time);
  http::async_read_header(m_stream, m_buffer, *m_parser,
                          [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_header(ec); });
}

void Editor_connection::on_header(beast::error_code ec)
{
  if(ec) return fail(ec);
  if(auto refusal = m_server.refuse(m_parser->get())) return write(std::move(*refusal), false);
  if(m_parser->get()[http::field::expect] == "100-continue")
  {
    static const std::string go_on = "HTTP/1.1 100 Continue\r\n\r\n";
    m_stream.expires_after(m_server.limits().write_time);
    return net::async_write(m_stream, net::buffer(go_on), [self = shared_from_this()](beast::error_code e, std::size_t) {
      if(e) return self->fail(e);
      self->read_body();
    });
  }
  read_body();
}

void Editor_connection::read_body()
{
  m_stream.expires_after(m_server.limits().body_time);
  http::async_read(m_stream, m_buffer, *m_parser,
                   [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_body(ec); });
}

void Editor_connection::on_body(beast::error_code ec)
{
  if(ec) return fail(ec);
  m_stream.expires_never(); // an edit may take a while; the client waits
  http::request<http::string_body> req = m_parser->release();
  const bool keep_alive = req.keep_alive();
  m_server.answer(std::move(req), [self = shared_from_this(), keep_alive](Http_answer a) {
    self->write(std::move(a), keep_alive);
  });
}

void Editor_connection::fail(beast::error_code ec)
{
  // a request the parser refuses is told why; a closed, silent or slow connection is dropped
  if(ec == http::error::body_limit)
    return write(error_answer(http::status::payload_too_large, "the request body is larger than " +
                                                                 std::to_string(m_server.limits().body_bytes) + " bytes", true),
                 false);
  if(ec == http::error::header_limit)
    return write(error_answer(http::status::request_header_fields_too_large,
                              "the request's headers are larger than " + std::to_string(m_server.limits().header_bytes) +
                                " bytes", true),
                 false);
  if(ec.category() == beast::error_code(http::error::end_of_stream).category() && ec != http::error::end_of_stream &&
     ec != http::error::partial_message)
    return write(error_answer(http::status::bad_request, "malformed HTTP request: " + ec.message(), true), false);
}

void Editor_connection::drain()
{
  // after an answer that leaves the request unread, what the client still sends is read and
  // dropped for a while (2 s, 64 MB): closing at once would reset the connection, and the
  // client could lose the answer
  if(m_discarded > (64u << 20)) return;
  m_stream.async_read_some(net::buffer(m_scratch), [self = shared_from_this()](beast::error_code ec, std::size_t n) {
    if(ec) return;
    self->m_discarded += n;
    self->drain();
  });
}

void Editor_connection::write(Http_answer answer, bool keep_alive)
{
  m_response = {};
  m_response.version(11);
  m_response.result(answer.status);
  m_response.set(http::field::content_type, answer.type);
  m_response.set(http::field::cache_control, "no-store");
  m_response.set("X-Content-Type-Options", "nosniff");
  m_response.set("X-Frame-Options", "DENY");
  m_response.set("Content-Security-Policy", "frame-ancestors 'none'");
  m_response.set("Referrer-Policy", "no-referrer"); // the token is in the page's address
  if(answer.status == http::status::method_not_allowed) m_response.set(http::field::allow, "GET, POST");
  m_response.body() = std::move(answer.body);
  m_response.keep_alive(keep_alive && !answer.close);
  m_response.prepare_payload();
  m_stream.expires_after(m_server.limits().write_time);
  http::async_write(m_stream, m_response, [self = shared_from_this()](beast::error_code ec, std::size_t) {
    if(ec) return;
    if(!self->m_response.keep_alive())
    {
      beast::error_code ignored;
      self->m_stream.socket().shutdown(tcp::socket::shutdown_send, ignored);
      self->m_discarded = 0;
      self->m_stream.expires_after(std::chrono::seconds(2));
      return self->drain();
    }
    self->read_header();
  });
}

} // namespace internal

/// Runs the editor until the process is stopped.
inline int run_editor(const Options& options)
{
  Editor_access access;
  if(!options.no_token) access.token = random_editor_token();
  const bool ipv6 = options.host.find(':') != std::string::npos;
  const std::string host_name = ipv6 ? "[" + options.host + "]" : options.host;
  std::string lower = host_name;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  access.hosts.push_back(lower);
  auto page = internal::read_editor_page(internal::editor_web_root(options));
  Editor_session session(options);
  internal::Editor_http_server server(session, std::move(page), access);
  access.port = server.listen(options.host, options.port); // before the first request is served
  if(options.host != "127.0.0.1" && options.host != "localhost" && options.host != "::1")
    std::cerr << "notice: --host " << options.host << ": the editor (which writes into " << options.output_dir
              << ") is open to other machines" << (options.no_token ? " without a token" : ", to whoever has its token")
              << std::endl;
  if(options.no_token)
    std::cerr << "notice: --no-token: any program or page that reaches " << host_name << ":" << access.port
              << " can drive the editor (only JSON requests naming this host are accepted)" << std::endl;
  std::cout << "editor: http://" << host_name << ":" << access.port << "/"
            << (access.token.empty() ? std::string() : "?token=" + access.token) << std::endl;
  server.run();
  return EXIT_SUCCESS;
}

} // namespace fs_app

#endif // CGAL_FEATURE_SEGMENTATION_DEMO_EDITOR_SERVER_H
