// An editor's side of a session with `ramus lsp` (RAMUS_EXE in the tests, bench/bench_lsp.cpp): the
// server runs as a child process on two pipes; the test writes framed JSON-RPC messages and reads
// what comes back, with a time limit so that a server that stops answering fails the test instead
// of hanging it.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>

namespace lsp_test {

using nlohmann::json;

class LspSession {
 public:
#ifdef RAMUS_EXE
  LspSession() : LspSession(RAMUS_EXE) {}
#endif
  // Runs `EXE lsp`.
  explicit LspSession(const std::string& exe) {
    int to_child[2], from_child[2];
    if (pipe(to_child) != 0 || pipe(from_child) != 0) throw std::runtime_error("pipe failed");
    pid_ = fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
      dup2(to_child[0], STDIN_FILENO);
      dup2(from_child[1], STDOUT_FILENO);
      close(to_child[1]);
      close(from_child[0]);
      execl(exe.c_str(), exe.c_str(), "lsp", static_cast<char*>(nullptr));
      _exit(127);
    }
    close(to_child[0]);
    close(from_child[1]);
    in_ = to_child[1];
    out_ = from_child[0];
    signal(SIGPIPE, SIG_IGN);  // a server that died must fail the test, not kill it
  }
  ~LspSession() {
    if (in_ >= 0) close(in_);
    if (out_ >= 0) close(out_);
    if (pid_ > 0 && !exited_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, nullptr, 0);
    }
  }
  LspSession(const LspSession&) = delete;
  LspSession& operator=(const LspSession&) = delete;

  // Raw bytes, for malformed input.
  void write_raw(const std::string& bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
      ssize_t n = ::write(in_, bytes.data() + done, bytes.size() - done);
      if (n <= 0) throw std::runtime_error("the server closed its input");
      done += std::size_t(n);
    }
  }
  void send_body(const std::string& body) {
    write_raw("Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body);
  }
  void send(const json& message) { send_body(message.dump()); }
  void request(int id, const std::string& method, json params = json::object()) {
    send({{"jsonrpc", "2.0"}, {"id", id}, {"method", method}, {"params", std::move(params)}});
  }
  void notify(const std::string& method, json params = json::object()) {
    send({{"jsonrpc", "2.0"}, {"method", method}, {"params", std::move(params)}});
  }

  // The next message from the server; nullopt when it closed its output or said nothing for
  // `seconds`.
  std::optional<json> receive(int seconds = 20) {
    std::string header;
    while (header.find("\r\n\r\n") == std::string::npos) {
      char c;
      if (!read_bytes(&c, 1, seconds)) return std::nullopt;
      header += c;
    }
    const std::string key = "Content-Length: ";
    std::size_t at = header.find(key);
    if (at == std::string::npos)
      throw std::runtime_error("response without Content-Length: " + header);
    std::size_t length = std::stoul(header.substr(at + key.size()));
    std::string body(length, '\0');
    if (length > 0 && !read_bytes(body.data(), length, seconds)) return std::nullopt;
    return json::parse(body);
  }

  // The response to request `id`, skipping notifications (diagnostics) on the way.
  json response(int id) {
    for (;;) {
      std::optional<json> m = receive();
      if (!m) throw std::runtime_error("no response to request " + std::to_string(id));
      if (m->contains("id") && (*m)["id"] == id && !m->contains("method")) return *m;
    }
  }

  // The next publishDiagnostics notification for `uri`.
  json diagnostics(const std::string& uri) {
    for (;;) {
      std::optional<json> m = receive();
      if (!m) throw std::runtime_error("no diagnostics for " + uri);
      if (m->value("method", "") == "textDocument/publishDiagnostics" &&
          (*m)["params"]["uri"] == uri)
        return (*m)["params"]["diagnostics"];
    }
  }

  // Closes the server's input and waits for it to exit; its exit code (-1 if killed).
  int wait_exit(int seconds = 20) {
    if (in_ >= 0) {
      close(in_);
      in_ = -1;
    }
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
    for (;;) {
      int status = 0;
      pid_t r = waitpid(pid_, &status, WNOHANG);
      if (r == pid_) {
        exited_ = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      }
      if (std::chrono::steady_clock::now() > deadline) return -2;
      usleep(10000);
    }
  }

 private:
  bool read_bytes(char* data, std::size_t n, int seconds) {
    std::size_t done = 0;
    while (done < n) {
      pollfd p{out_, POLLIN, 0};
      if (poll(&p, 1, seconds * 1000) <= 0) return false;
      ssize_t r = ::read(out_, data + done, n - done);
      if (r <= 0) return false;
      done += std::size_t(r);
    }
    return true;
  }

  pid_t pid_ = -1;
  int in_ = -1, out_ = -1;
  bool exited_ = false;
};

}  // namespace lsp_test
