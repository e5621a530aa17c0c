#pragma once
// The real `villa annotate` in a private tmux server (tmux is a declared dependency): send keys, raw
// bytes and bracketed pastes, read the screen and the cursor. Shared by the terminal-driven tests.
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <catch2/catch.hpp>

namespace villa::annotator::test {

inline std::string RunShell(const std::string& command, int* status = nullptr) {
  std::string out;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return out;
  char buffer[4096];
  std::size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
  int rc = ::pclose(pipe);
  if (status) *status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  return out;
}

inline std::string Quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

inline bool HaveTmux() {
  int status = 0;
  RunShell("command -v tmux >/dev/null 2>&1", &status);
  return status == 0;
}

// One private tmux server running `villa annotate DIR ARGS` in a width x height window. `env` is put
// after the UTF-8 defaults, so "LC_ALL=C LANG=C" makes a plain-ASCII session.
class Terminal {
 public:
  Terminal(const std::filesystem::path& dir, int width = 80, int height = 24, const std::string& env = "",
           const std::string& args = "") {
    static int counter = 0;
    socket_ = "villa-annotator-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    std::string command = "exec env LANG=C.UTF-8 LC_ALL=C.UTF-8 TERM=xterm-256color " + env + " " +
                          Quote(VILLA_BINARY) + " annotate " + Quote(dir.string()) + " " + args;
    Tmux("new-session -d -s t -x " + std::to_string(width) + " -y " + std::to_string(height) + " " + Quote(command));
  }
  ~Terminal() { Tmux("kill-server 2>/dev/null"); }
  Terminal(const Terminal&) = delete;
  Terminal& operator=(const Terminal&) = delete;

  std::string Tmux(const std::string& args, int* status = nullptr) const {
    return RunShell("env -u TMUX tmux -f /dev/null -L " + socket_ + " " + args, status);
  }
  std::string Screen() const { return Tmux("capture-pane -p -t t 2>/dev/null"); }
  std::vector<std::string> Lines() const {
    std::vector<std::string> lines;
    std::istringstream in(Screen());
    std::string line;
    while (std::getline(in, line)) lines.push_back(line);
    return lines;
  }
  // Key names as tmux spells them ("Enter", "Escape", "C-u", "M-b", "End").
  void Keys(const std::string& keys) const { Tmux("send-keys -t t " + keys); }
  // Text typed literally, character by character.
  void Type(const std::string& text) const { Tmux("send-keys -t t -l -- " + Quote(text)); }
  // Raw bytes, in hex ("ff", "1b 5b 34 7e").
  void Bytes(const std::string& hex) const { Tmux("send-keys -t t -H " + hex); }
  // A paste as a terminal delivers it: bracketed when the program asked for bracketed paste, with
  // line feeds turned into carriage returns as a terminal sends Enter.
  void Paste(const std::string& text) const {
    Tmux("set-buffer -b p -- " + Quote(text));
    Tmux("paste-buffer -p -d -b p -t t");
  }
  bool Alive() const {
    int status = 0;
    Tmux("has-session -t t 2>/dev/null", &status);
    return status == 0;
  }
  int Pid() const { return std::atoi(Tmux("display -p -t t '#{pane_pid}'").c_str()); }
  int CursorX() const { return std::atoi(Tmux("display -p -t t '#{cursor_x}'").c_str()); }
  int CursorY() const { return std::atoi(Tmux("display -p -t t '#{cursor_y}'").c_str()); }

  // Waits (up to 10 s) until the screen shows `text`.
  bool WaitFor(const std::string& text) const {
    for (int i = 0; i < 200; ++i) {
      if (Screen().find(text) != std::string::npos) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
  }
  // Waits (up to 10 s) until the screen no longer shows `text`.
  bool WaitGone(const std::string& text) const {
    for (int i = 0; i < 200; ++i) {
      if (Screen().find(text) == std::string::npos) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
  }
  // Opens the in-place editor with `key` ("e" coarse, "E" fine) and clears its text; false when the
  // editor did not show.
  bool EditCleared(const std::string& key) const {
    Keys(key);
    if (!WaitFor("Enter: save")) return false;
    Keys("C-u");
    return true;
  }
  // q, and the tool is gone within 10 s.
  bool Quit() const {
    Keys("q");
    return WaitForExit();
  }
  bool WaitForExit() const {
    for (int i = 0; i < 200; ++i) {
      if (!Alive()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
  }

 private:
  std::string socket_;
};

#define REQUIRE_SCREEN(term, text)        \
  do {                                    \
    bool shown = (term).WaitFor(text);    \
    INFO("screen:\n" << (term).Screen()); \
    REQUIRE(shown);                       \
  } while (false)

}  // namespace villa::annotator::test
