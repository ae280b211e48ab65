#pragma once
// The live view's HTTP and WebSocket server, on civetweb (Debian's libcivetweb): the page's files at their
// paths and WebSockets at the settings' paths (the page's /ws; /foxglove, where the client must ask for the
// Foxglove subprotocol). It only moves bytes: who joined, what a client sent and who left are events
// the owner takes (takeEvents) on its own thread; what to send each client is the owner's to say (send).
// Each client has a writer thread and a queue, so a slow browser never stalls the bus: one whose queue
// grows past max_queued_bytes is closed (the page reconnects and starts from a fresh snapshot).

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

struct mg_context;
struct mg_connection;

namespace ifar::view {

/// One file of the page.
struct WebAsset {
  std::string_view path;          // "/index.html"
  std::string_view content_type;  // "text/html; charset=utf-8"
  std::string_view content;
};

/// A WebSocket path. When `subprotocol` is set, a client must offer it in its handshake (civetweb names it in
/// the answer); one that does not is refused.
struct SocketEndpoint {
  std::string path;
  std::string subprotocol;
};

struct WebServerSettings {
  std::string address = "0.0.0.0";  // every interface: any browser on the vehicle's network
  int port = 8080;                  // 0: any free port (port() says which)
  std::vector<WebAsset> assets;     // "/" serves "/index.html"
  std::string asset_directory;      // when set, files are read from here on each request instead
  std::size_t max_queued_bytes = 16U << 20U;
  std::vector<SocketEndpoint> sockets = {{"/ws", ""}};
};

using ClientId = std::uint64_t;

struct ClientEvent {
  enum class Kind : std::uint8_t { kJoined, kText, kBinary, kLeft };
  Kind kind = Kind::kJoined;
  ClientId client = 0;
  std::string text;      // kText, kBinary: what the client sent; kJoined: its address
  std::string endpoint;  // the path of the socket it joined on
};

struct WebFrame {
  bool binary = false;
  std::string bytes;
};

inline WebFrame textFrame(std::string text)
{
  return WebFrame{false, std::move(text)};
}

/// What to send whom: the web server's send in ifar view, a recorder in tests.
using Send = std::function<void(ClientId client, const std::vector<WebFrame>& frames)>;

class WebServer {
 public:
  /// Listens at once. Throws std::runtime_error naming the address and port when it cannot.
  explicit WebServer(WebServerSettings settings);
  ~WebServer();
  WebServer(const WebServer&) = delete;
  WebServer& operator=(const WebServer&) = delete;

  /// The port it listens on (the one chosen when settings asked for 0).
  int port() const { return port_; }

  /// What happened since the last call, in order.
  std::vector<ClientEvent> takeEvents();
  /// Queues `frames` for `client` (nothing when it has left).
  void send(ClientId client, const std::vector<WebFrame>& frames);
  std::size_t clientCount() const;

  struct Client;
  struct Endpoint;

 private:
  static int serveFile(mg_connection* connection, void* server);
  static int acceptSocket(const mg_connection* connection, void* endpoint);
  static void socketReady(mg_connection* connection, void* endpoint);
  static int socketData(mg_connection* connection, int bits, char* data, std::size_t length, void* endpoint);
  static void socketClosed(const mg_connection* connection, void* endpoint);
  void pushEvent(ClientEvent event);

  WebServerSettings settings_;
  mg_context* context_ = nullptr;
  int port_ = 0;
  mutable std::mutex mutex_;
  ClientId next_client_ = 1;
  std::vector<std::unique_ptr<Endpoint>> endpoints_;  // civetweb holds pointers to them until mg_stop
  std::map<ClientId, std::shared_ptr<Client>> clients_;
  std::vector<ClientEvent> events_;
};

}  // namespace ifar::view
