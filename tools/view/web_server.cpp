#include "tools/view/web_server.hpp"

#include <civetweb.h>

#include <condition_variable>
#include <deque>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <utility>

namespace ifar::view {
namespace {

// Features asked of civetweb's library: WebSockets (16, as mg_check_feature numbers them).
constexpr unsigned kWebSocketFeature = 16;
// Idle sockets are pinged this often; a browser that stops answering is dropped by civetweb.
constexpr const char* kPingIntervalMs = "5000";
// Worker threads: each open WebSocket holds one, the page's files need a few more.
constexpr const char* kThreads = "24";

std::string contentTypeOf(const std::string& path)
{
  const auto ends = [&path](const std::string& suffix) {
    return path.size() >= suffix.size() &&
           path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  if (ends(".html")) {
    return "text/html; charset=utf-8";
  }
  if (ends(".js")) {
    return "text/javascript; charset=utf-8";
  }
  if (ends(".css")) {
    return "text/css; charset=utf-8";
  }
  if (ends(".svg")) {
    return "image/svg+xml";
  }
  return "application/octet-stream";
}

void reply(mg_connection* connection, int status, const std::string& content_type, std::string_view body)
{
  // Through civetweb's header calls, so it knows the length and closes or keeps the connection itself.
  mg_response_header_start(connection, status);
  mg_response_header_add(connection, "Content-Type", content_type.c_str(), -1);
  mg_response_header_add(connection, "Content-Length", std::to_string(body.size()).c_str(), -1);
  mg_response_header_add(connection, "Cache-Control", "no-cache", -1);
  mg_response_header_send(connection);
  mg_write(connection, body.data(), body.size());
}

}  // namespace

struct WebServer::Endpoint {
  WebServer* server = nullptr;
  std::string path;
  std::string subprotocol;
  const char* subprotocol_names[1] = {nullptr};
  mg_websocket_subprotocols subprotocols{};
};

struct WebServer::Client {
  ClientId id = 0;
  std::string endpoint;
  mg_connection* connection = nullptr;
  std::size_t max_queued_bytes = 0;
  std::mutex mutex;
  std::condition_variable wake;
  std::deque<WebFrame> queue;
  std::size_t queued_bytes = 0;
  bool closed = false;      // the socket is gone: the writer ends
  bool overflowed = false;  // too far behind: the writer closes the socket
  std::thread writer;

  void write()
  {
    for (;;) {
      WebFrame frame;
      {
        std::unique_lock<std::mutex> lock(mutex);
        wake.wait(lock, [this] { return closed || overflowed || !queue.empty(); });
        if (closed) {
          return;
        }
        if (overflowed) {
          lock.unlock();
          mg_lock_connection(connection);
          mg_websocket_write(connection, MG_WEBSOCKET_OPCODE_CONNECTION_CLOSE, "", 0);
          mg_unlock_connection(connection);
          return;
        }
        frame = std::move(queue.front());
        queue.pop_front();
        queued_bytes -= frame.bytes.size();
      }
      mg_lock_connection(connection);
      const int written =
          mg_websocket_write(connection, frame.binary ? MG_WEBSOCKET_OPCODE_BINARY : MG_WEBSOCKET_OPCODE_TEXT,
                             frame.bytes.data(), frame.bytes.size());
      mg_unlock_connection(connection);
      if (written <= 0) {
        return;  // the socket failed; civetweb closes it and calls socketClosed
      }
    }
  }
};

WebServer::WebServer(WebServerSettings settings) : settings_(std::move(settings))
{
  mg_init_library(kWebSocketFeature);
  if (mg_check_feature(kWebSocketFeature) == 0) {
    mg_exit_library();
    throw std::runtime_error("this civetweb library was built without WebSocket support");
  }
  const std::string listening = settings_.address + ":" + std::to_string(settings_.port);
  const char* options[] = {
      "listening_ports",      listening.c_str(), "num_threads", kThreads, "enable_websocket_ping_pong", "yes",
      "websocket_timeout_ms", kPingIntervalMs,   nullptr};
  mg_callbacks callbacks{};
  // civetweb prints its errors to stderr itself; nothing else is needed from these callbacks.
  context_ = mg_start(&callbacks, this, options);
  if (context_ == nullptr) {
    mg_exit_library();
    throw std::runtime_error("cannot listen on " + listening + " (address in use, or not this host's)");
  }
  mg_server_port ports[4]{};
  const int count = mg_get_server_ports(context_, 4, ports);
  port_ = count > 0 ? ports[0].port : settings_.port;
  mg_set_request_handler(context_, "/", &WebServer::serveFile, this);
  for (const SocketEndpoint& socket : settings_.sockets) {
    auto endpoint = std::make_unique<Endpoint>();
    endpoint->server = this;
    endpoint->path = socket.path;
    endpoint->subprotocol = socket.subprotocol;
    endpoint->subprotocol_names[0] = endpoint->subprotocol.c_str();
    endpoint->subprotocols.nb_subprotocols = endpoint->subprotocol.empty() ? 0 : 1;
    endpoint->subprotocols.subprotocols = endpoint->subprotocol_names;
    mg_set_websocket_handler_with_subprotocols(
        context_, endpoint->path.c_str(), endpoint->subprotocol.empty() ? nullptr : &endpoint->subprotocols,
        &WebServer::acceptSocket, &WebServer::socketReady, &WebServer::socketData, &WebServer::socketClosed,
        endpoint.get());
    endpoints_.push_back(std::move(endpoint));
  }
}

WebServer::~WebServer()
{
  mg_stop(context_);  // closes every socket (socketClosed joins each writer) and ends civetweb's threads
  // Any client civetweb did not report closed still has its writer: end it before its socket is gone.
  for (auto& [id, client] : clients_) {
    {
      const std::lock_guard<std::mutex> lock(client->mutex);
      client->closed = true;
    }
    client->wake.notify_all();
    if (client->writer.joinable()) {
      client->writer.join();
    }
  }
  mg_exit_library();
}

int WebServer::serveFile(mg_connection* connection, void* server)
{
  const auto& self = *static_cast<WebServer*>(server);
  const mg_request_info* request = mg_get_request_info(connection);
  std::string path = request->local_uri != nullptr ? request->local_uri : "/";
  if (path == "/") {
    path = "/index.html";
  }
  if (!self.settings_.asset_directory.empty()) {
    // civetweb's local_uri is already cleaned of "." and ".." segments; refuse any that remain anyway.
    if (path.find("..") == std::string::npos) {
      std::ifstream file(self.settings_.asset_directory + path, std::ios::binary);
      if (file) {
        std::ostringstream content;
        content << file.rdbuf();
        reply(connection, 200, contentTypeOf(path), content.str());
        return 200;
      }
    }
  } else {
    for (const WebAsset& asset : self.settings_.assets) {
      if (asset.path == path) {
        reply(connection, 200, std::string(asset.content_type), asset.content);
        return 200;
      }
    }
  }
  reply(connection, 404, "text/plain; charset=utf-8", "not found: " + path + "\n");
  return 404;
}

int WebServer::acceptSocket(const mg_connection* connection, void* endpoint)
{
  const auto& socket = *static_cast<const Endpoint*>(endpoint);
  if (socket.subprotocol.empty()) {
    return 0;  // every client is welcome
  }
  // civetweb picks the subprotocol before this call: ours when the client listed it among others, whatever
  // it asked for when it asked for one only, none when it asked for none.
  const char* accepted = mg_get_request_info(connection)->acceptedWebSocketSubprotocol;
  return accepted != nullptr && socket.subprotocol == accepted ? 0 : 1;
}

void WebServer::socketReady(mg_connection* connection, void* endpoint)
{
  const auto& socket = *static_cast<const Endpoint*>(endpoint);
  WebServer& self = *socket.server;
  auto client = std::make_shared<Client>();
  client->endpoint = socket.path;
  client->connection = connection;
  client->max_queued_bytes = self.settings_.max_queued_bytes;
  {
    const std::lock_guard<std::mutex> lock(self.mutex_);
    client->id = self.next_client_++;
    self.clients_[client->id] = client;
  }
  mg_set_user_connection_data(connection, client.get());
  client->writer = std::thread([raw = client.get()] { raw->write(); });
  const mg_request_info* request = mg_get_request_info(connection);
  self.pushEvent({ClientEvent::Kind::kJoined, client->id, request->remote_addr, socket.path});
}

int WebServer::socketData(mg_connection* connection, int bits, char* data, std::size_t length, void* endpoint)
{
  WebServer& self = *static_cast<const Endpoint*>(endpoint)->server;
  const int opcode = bits & 0x0F;
  if (opcode == MG_WEBSOCKET_OPCODE_CONNECTION_CLOSE) {
    return 0;
  }
  const auto* client = static_cast<const Client*>(mg_get_user_connection_data(connection));
  if (client != nullptr && (opcode == MG_WEBSOCKET_OPCODE_TEXT || opcode == MG_WEBSOCKET_OPCODE_BINARY)) {
    self.pushEvent(
        {opcode == MG_WEBSOCKET_OPCODE_TEXT ? ClientEvent::Kind::kText : ClientEvent::Kind::kBinary,
         client->id, std::string(data, length), client->endpoint});
  }
  return 1;
}

void WebServer::socketClosed(const mg_connection* connection, void* endpoint)
{
  WebServer& self = *static_cast<const Endpoint*>(endpoint)->server;
  auto* raw = static_cast<Client*>(mg_get_user_connection_data(connection));
  if (raw == nullptr) {
    return;
  }
  std::shared_ptr<Client> client;
  {
    const std::lock_guard<std::mutex> lock(self.mutex_);
    const auto found = self.clients_.find(raw->id);
    if (found == self.clients_.end()) {
      return;
    }
    client = found->second;
    self.clients_.erase(found);
  }
  {
    const std::lock_guard<std::mutex> lock(client->mutex);
    client->closed = true;
  }
  client->wake.notify_all();
  client->writer.join();
  self.pushEvent({ClientEvent::Kind::kLeft, client->id, {}, client->endpoint});
}

void WebServer::pushEvent(ClientEvent event)
{
  const std::lock_guard<std::mutex> lock(mutex_);
  events_.push_back(std::move(event));
}

std::vector<ClientEvent> WebServer::takeEvents()
{
  const std::lock_guard<std::mutex> lock(mutex_);
  std::vector<ClientEvent> events;
  events.swap(events_);
  return events;
}

void WebServer::send(ClientId id, const std::vector<WebFrame>& frames)
{
  std::shared_ptr<Client> client;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto found = clients_.find(id);
    if (found == clients_.end()) {
      return;
    }
    client = found->second;
  }
  {
    const std::lock_guard<std::mutex> lock(client->mutex);
    for (const WebFrame& frame : frames) {
      if (client->overflowed) {
        break;
      }
      client->queued_bytes += frame.bytes.size();
      client->queue.push_back(frame);
      if (client->queued_bytes > client->max_queued_bytes) {
        client->overflowed = true;
        client->queue.clear();
        client->queued_bytes = 0;
      }
    }
  }
  client->wake.notify_all();
}

std::size_t WebServer::clientCount() const
{
  const std::lock_guard<std::mutex> lock(mutex_);
  return clients_.size();
}

}  // namespace ifar::view
