// longer than 300 lines because the Beast server is kept in this one file (Beast is slow to compile)
// The only file that includes Boost.Beast. One io_context on one thread runs every connection,
// so sessions need no strand; the mutex guards only what the LCM thread also touches (the
// clients' queues, the kept frames, the inbox, the counters).

#include "web_console/console_server.hpp"

#include "common/clock.hpp"
#include "web_console/client_queue.hpp"
#include "web_console/origin_rule.hpp"

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include <atomic>
#include <chrono>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>

namespace refloc {

namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
namespace net = boost::asio;
using tcp = net::ip::tcp;

namespace {

class WebSocketSession;

}  // namespace

struct ConsoleServer::Impl {
  Impl(const ConsoleServerConfig& c, const RequestValidator& v, std::map<std::string, WwwFile> f)
      : config(c), validator(v), files(std::move(f)), acceptor(ioc), stall_timer(ioc) {}

  struct Client {
    ClientQueue queue;
    std::shared_ptr<WebSocketSession> session;
  };

  void accept_next();
  void check_stalled_clients();
  void flush_all();
  void count(const std::string& name, int64_t n = 1) {
    std::lock_guard<std::mutex> lock(mutex);
    counters[name] += n;
  }
  bool full() const {
    std::lock_guard<std::mutex> lock(mutex);
    return clients.size() >= config.max_clients;
  }
  /// Registers a client and queues the kept frames for it; 0 when the limit is reached.
  uint64_t add_client(std::shared_ptr<WebSocketSession> session);
  void remove_client(uint64_t id);
  std::shared_ptr<const std::string> next_frame(uint64_t id);
  void write_done(uint64_t id);
  /// Judges a client's message, queues the command and answers that client (command_result).
  void on_client_message(uint64_t id, const std::string& text);

  ConsoleServerConfig config;
  RequestValidator validator;
  std::map<std::string, WwwFile> files;
  net::io_context ioc;
  tcp::acceptor acceptor;
  net::steady_timer stall_timer;
  std::thread thread;
  std::atomic<bool> flush_posted{false};

  mutable std::mutex mutex;  // guards everything below
  std::map<uint64_t, Client> clients;
  uint64_t next_client_id = 1;
  std::map<std::string, std::shared_ptr<const std::string>> latest;
  std::deque<ConsoleCommand> inbox;
  std::map<std::string, int64_t> counters;
};

namespace {

class WebSocketSession : public std::enable_shared_from_this<WebSocketSession> {
 public:
  WebSocketSession(ConsoleServer::Impl& server, tcp::socket socket)
      : server_(server), ws_(std::move(socket)) {}

  void accept(http::request<http::string_body> request) {
    websocket::stream_base::timeout timeout =
        websocket::stream_base::timeout::suggested(beast::role_type::server);
    // A browser answers pings by itself: one that vanished without closing is gone after 30 s
    // even while no frame is pending (the stall check catches it sooner when frames are).
    timeout.idle_timeout = std::chrono::seconds(30);
    timeout.keep_alive_pings = true;
    ws_.set_option(timeout);
    ws_.read_message_max(server_.config.max_message_bytes);
    id_ = server_.add_client(shared_from_this());
    if (id_ == 0) return;  // over the limit: counted; the socket closes with this session
    ws_.async_accept(request, [self = shared_from_this()](beast::error_code ec) {
      if (ec) return self->close();
      self->accepted_ = true;
      self->read_next();
      self->write_next();
    });
  }

  void write_next() {
    if (!accepted_ || closed_) return;
    std::shared_ptr<const std::string> frame = server_.next_frame(id_);
    if (!frame) return;
    ws_.text(true);
    ws_.async_write(net::buffer(*frame), [self = shared_from_this(), frame](beast::error_code ec, size_t) {
      self->server_.write_done(self->id_);
      if (ec) return self->close();
      self->server_.count("frames_sent");
      self->write_next();
    });
  }

  void close() {
    if (closed_) return;
    closed_ = true;
    beast::error_code ignored;
    beast::get_lowest_layer(ws_).socket().shutdown(tcp::socket::shutdown_both, ignored);
    beast::get_lowest_layer(ws_).socket().close(ignored);
    server_.remove_client(id_);
  }

 private:
  void read_next() {
    buffer_.clear();
    ws_.async_read(buffer_, [self = shared_from_this()](beast::error_code ec, size_t) {
      if (ec == websocket::error::message_too_big) self->server_.count("requests_refused_too_large");
      // Beast's idle timeout: no frame (not even a pong to its ping) from the client for 30 s.
      if (ec == beast::error::timeout) self->server_.count("clients_dropped_idle");
      if (ec) return self->close();
      if (!self->ws_.got_text()) {
        self->server_.count("requests_refused_not_json");
      } else {
        self->server_.on_client_message(self->id_, beast::buffers_to_string(self->buffer_.data()));
      }
      self->read_next();
    });
  }

  ConsoleServer::Impl& server_;
  websocket::stream<beast::tcp_stream> ws_;
  beast::flat_buffer buffer_;
  uint64_t id_ = 0;
  bool accepted_ = false;
  bool closed_ = false;
};

/// One HTTP request: a file, or the WebSocket upgrade handed to a WebSocketSession.
class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(ConsoleServer::Impl& server, tcp::socket socket)
      : server_(server), stream_(std::move(socket)) {}

  void run() {
    parser_.emplace();
    parser_->body_limit(server_.config.max_message_bytes);
    parser_->header_limit(16 * 1024);
    stream_.expires_after(std::chrono::seconds(10));
    http::async_read(stream_, buffer_, *parser_, [self = shared_from_this()](beast::error_code ec, size_t) {
      if (ec) {
        self->server_.count("http_bad_requests");
        return;
      }
      self->handle(self->parser_->release());
    });
  }

 private:
  void handle(http::request<http::string_body> request) {
    if (websocket::is_upgrade(request)) return upgrade(std::move(request));
    server_.count("http_requests");
    if (request.method() != http::verb::get && request.method() != http::verb::head)
      return reply(request, http::status::method_not_allowed, "text/plain", "GET only\n");
    std::string target(request.target());
    target = target.substr(0, target.find('?'));
    const auto file = server_.files.find(target);
    if (file == server_.files.end()) {
      server_.count("http_not_found");
      return reply(request, http::status::not_found, "text/plain", "not found\n");
    }
    reply(request, http::status::ok, file->second.content_type, file->second.body);
  }

  void upgrade(http::request<http::string_body> request) {
    const std::string origin(request[http::field::origin]);
    const std::string host(request[http::field::host]);
    if (judge_origin(origin, host, server_.config.allowed_origins) == OriginVerdict::kRefused) {
      server_.count("clients_refused_origin");
      return reply(request, http::status::forbidden, "text/plain", "origin refused\n");
    }
    if (server_.full()) {
      server_.count("clients_refused_limit");
      return reply(request, http::status::service_unavailable, "text/plain", "too many clients\n");
    }
    stream_.expires_never();
    auto session = std::make_shared<WebSocketSession>(server_, stream_.release_socket());
    session->accept(std::move(request));
  }

  void reply(const http::request<http::string_body>& request, http::status status, const std::string& type,
             const std::string& body) {
    auto response = std::make_shared<http::response<http::string_body>>(status, request.version());
    response->set(http::field::content_type, type);
    response->set(http::field::cache_control, "no-cache");
    response->keep_alive(false);
    if (request.method() != http::verb::head) response->body() = body;
    response->prepare_payload();
    http::async_write(stream_, *response, [self = shared_from_this(), response](beast::error_code, size_t) {
      beast::error_code ignored;
      self->stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
    });
  }

  ConsoleServer::Impl& server_;
  beast::tcp_stream stream_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
};

}  // namespace

void ConsoleServer::Impl::accept_next() {
  acceptor.async_accept(ioc, [this](beast::error_code ec, tcp::socket socket) {
    if (ec == net::error::operation_aborted) return;
    if (!ec) std::make_shared<HttpSession>(*this, std::move(socket))->run();
    accept_next();
  });
}

void ConsoleServer::Impl::check_stalled_clients() {
  stall_timer.expires_after(std::chrono::milliseconds(250));
  stall_timer.async_wait([this](beast::error_code ec) {
    if (ec) return;
    const int64_t now = monotonic_us();
    const auto timeout_us = static_cast<int64_t>(config.stalled_client_timeout_s * 1e6);
    std::vector<std::shared_ptr<WebSocketSession>> stalled;
    {
      std::lock_guard<std::mutex> lock(mutex);
      for (auto& [id, client] : clients)
        if (client.queue.stalled(now, timeout_us)) stalled.push_back(client.session);
      counters["clients_dropped_stalled"] += static_cast<int64_t>(stalled.size());
    }
    for (auto& s : stalled) s->close();
    check_stalled_clients();
  });
}

void ConsoleServer::Impl::flush_all() {
  flush_posted = false;
  std::vector<std::shared_ptr<WebSocketSession>> sessions;
  {
    std::lock_guard<std::mutex> lock(mutex);
    for (auto& [id, client] : clients)
      if (!client.queue.writing() && client.queue.size() > 0) sessions.push_back(client.session);
  }
  for (auto& s : sessions) s->write_next();
}

uint64_t ConsoleServer::Impl::add_client(std::shared_ptr<WebSocketSession> session) {
  std::lock_guard<std::mutex> lock(mutex);
  if (clients.size() >= config.max_clients) {
    ++counters["clients_refused_limit"];
    return 0;
  }
  const uint64_t id = next_client_id++;
  Client& client =
      clients.emplace(id, Client{ClientQueue(config.client_queue_frames), std::move(session)}).first->second;
  for (const auto& [key, text] : latest) client.queue.push(text);
  ++counters["clients_accepted"];
  return id;
}

void ConsoleServer::Impl::remove_client(uint64_t id) {
  std::lock_guard<std::mutex> lock(mutex);
  const auto it = clients.find(id);
  if (it == clients.end()) return;
  clients.erase(it);
}

std::shared_ptr<const std::string> ConsoleServer::Impl::next_frame(uint64_t id) {
  std::lock_guard<std::mutex> lock(mutex);
  const auto it = clients.find(id);
  return it == clients.end() ? nullptr : it->second.queue.start_write(monotonic_us());
}

void ConsoleServer::Impl::write_done(uint64_t id) {
  std::lock_guard<std::mutex> lock(mutex);
  const auto it = clients.find(id);
  if (it != clients.end()) it->second.queue.write_done();
}

void ConsoleServer::Impl::on_client_message(uint64_t id, const std::string& text) {
  const RequestVerdict verdict = validator.judge(text);
  {
    std::lock_guard<std::mutex> lock(mutex);
    const char* refusal = nullptr;
    if (!verdict.command) {
      ++counters[std::string("requests_refused_") + verdict.refusal];
    } else if (inbox.size() >= config.command_inbox) {
      ++counters["requests_refused_inbox_full"];
      refusal = "inbox_full";
    } else {
      inbox.push_back(*verdict.command);
      ++counters["requests_accepted"];
    }
    const auto client = clients.find(id);
    if (client != clients.end() && !client->second.queue.push(std::make_shared<const std::string>(
                                       command_result_frame(verdict, refusal))))
      ++counters["frames_dropped"];
  }
  if (!flush_posted.exchange(true)) net::post(ioc, [this] { flush_all(); });
}

ConsoleServer::ConsoleServer(const ConsoleServerConfig& config, const RequestValidator& validator,
                             std::map<std::string, WwwFile> files)
    : impl_(std::make_unique<Impl>(config, validator, std::move(files))) {}

ConsoleServer::~ConsoleServer() { stop(); }

void ConsoleServer::start() {
  Impl& s = *impl_;
  const std::string where = s.config.listen_address + ":" + std::to_string(s.config.port);
  beast::error_code ec;
  const net::ip::address address = net::ip::make_address(s.config.listen_address, ec);
  if (ec) throw std::runtime_error("listen_address " + s.config.listen_address + ": not an IP address");
  const tcp::endpoint endpoint(address, s.config.port);
  s.acceptor.open(endpoint.protocol(), ec);
  if (!ec) s.acceptor.set_option(net::socket_base::reuse_address(true), ec);
  if (!ec) s.acceptor.bind(endpoint, ec);
  if (!ec) s.acceptor.listen(net::socket_base::max_listen_connections, ec);
  if (ec) throw std::runtime_error("cannot listen on " + where + ": " + ec.message());
  s.accept_next();
  s.check_stalled_clients();
  s.thread = std::thread([&s] { s.ioc.run(); });
}

uint16_t ConsoleServer::port() const {
  beast::error_code ec;
  const tcp::endpoint endpoint = impl_->acceptor.local_endpoint(ec);
  return ec ? 0 : endpoint.port();
}

void ConsoleServer::stop() {
  Impl& s = *impl_;
  if (!s.thread.joinable()) return;
  net::post(s.ioc, [&s] {
    beast::error_code ignored;
    s.acceptor.close(ignored);
    s.stall_timer.cancel();
    std::vector<std::shared_ptr<WebSocketSession>> sessions;
    {
      std::lock_guard<std::mutex> lock(s.mutex);
      for (auto& [id, client] : s.clients) sessions.push_back(client.session);
    }
    for (auto& session : sessions) session->close();
  });
  // Connections still finishing are not waited for: at most a second, then the loop is stopped.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
  while (!s.ioc.stopped() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  s.ioc.stop();
  s.thread.join();
}

void ConsoleServer::send(const ConsoleFrame& frame) {
  Impl& s = *impl_;
  {
    std::lock_guard<std::mutex> lock(s.mutex);
    if (!frame.latest_key.empty()) s.latest[frame.latest_key] = frame.text;
    if (!frame.send_now) return;
    for (auto& [id, client] : s.clients)
      if (!client.queue.push(frame.text)) ++s.counters["frames_dropped"];
  }
  if (!s.flush_posted.exchange(true)) net::post(s.ioc, [&s] { s.flush_all(); });
}

std::vector<ConsoleCommand> ConsoleServer::take_commands() {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  std::vector<ConsoleCommand> commands(impl_->inbox.begin(), impl_->inbox.end());
  impl_->inbox.clear();
  return commands;
}

std::map<std::string, int64_t> ConsoleServer::counters() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  std::map<std::string, int64_t> c = impl_->counters;
  c["clients"] = static_cast<int64_t>(impl_->clients.size());
  return c;
}

}  // namespace refloc
