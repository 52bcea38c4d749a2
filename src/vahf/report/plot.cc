#include "vahf/report/plot.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <regex>
#include <string>
#include <string_view>

#include "vahf/report/figure.h"

extern char** environ;  // POSIX: the environment, passed on to gnuplot

namespace vahf::report {
namespace {

std::string FirstLine(const std::string& script) {
  const std::string line = script.substr(0, script.find('\n'));
  return line.size() > 80 ? line.substr(0, 77) + "..." : line;
}

bool SetsTerminal(const std::string& script) {
  static const std::regex set_term(R"((^|\n)[ \t]*set[ \t]+term)");
  return std::regex_search(script, set_term);
}

// Writes all of `bytes` to `fd` with SIGPIPE blocked in this thread, so that a
// gnuplot that quit early makes write() fail with EPIPE instead of killing
// the process; a SIGPIPE raised here is consumed before the mask is restored.
bool WriteAll(int fd, std::string_view bytes) {
  sigset_t pipe_only, previous, pending;
  sigemptyset(&pipe_only);
  sigaddset(&pipe_only, SIGPIPE);
  sigpending(&pending);
  const bool was_pending = sigismember(&pending, SIGPIPE) == 1;
  pthread_sigmask(SIG_BLOCK, &pipe_only, &previous);
  bool ok = true;
  while (!bytes.empty()) {
    const ssize_t n = write(fd, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      ok = false;
      if (errno == EPIPE && !was_pending) {
        const timespec zero{0, 0};
        while (sigtimedwait(&pipe_only, nullptr, &zero) < 0 && errno == EINTR) {
        }
      }
      break;
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  return ok;
}

std::string ReadAll(std::FILE* file) {
  std::string out;
  std::rewind(file);
  char buffer[4096];
  std::size_t got;
  while ((got = std::fread(buffer, 1, sizeof buffer, file)) > 0) out.append(buffer, got);
  while (!out.empty() && std::isspace(static_cast<unsigned char>(out.back())))
    out.pop_back();
  return out;
}

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

}  // namespace

void RenderPlot(const std::string& gnuplot_script, const std::string& png_path) {
  const std::string name =
      "the plot script beginning '" + FirstLine(gnuplot_script) + "'";
  // A failed plot leaves no file: gnuplot may have created an empty one.
  const auto fail = [&](const std::string& what, const std::string& output) {
    std::remove(png_path.c_str());
    throw PlotError(what + " on " + name + (output.empty() ? "" : ":\n" + output));
  };
  if (std::remove(png_path.c_str()) != 0 && errno != ENOENT) {
    fail("cannot remove the old " + png_path + ": " + std::strerror(errno), "");
  }
  std::string script;
  if (!SetsTerminal(gnuplot_script))
    script += "set terminal pngcairo size 800,500 noenhanced\n";
  script +=
      "set output " + GnuplotString(png_path) + "\n" + gnuplot_script + "\nset output\n";

  // gnuplot's stdout and stderr go to an anonymous file, read once it exited:
  // a pipe could fill and block it while this side still writes the script.
  const std::unique_ptr<std::FILE, FileCloser> output(std::tmpfile());
  if (!output)
    fail(std::string("cannot create a temporary file: ") + std::strerror(errno), "");
  int script_pipe[2];
  if (pipe2(script_pipe, O_CLOEXEC) != 0) {
    fail(std::string("cannot create a pipe: ") + std::strerror(errno), "");
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, script_pipe[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, fileno(output.get()), STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, fileno(output.get()), STDERR_FILENO);
  char program[] = "gnuplot";
  char* argv[] = {program, nullptr};
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, program, &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  close(script_pipe[0]);
  if (spawned != 0) {
    close(script_pipe[1]);
    fail(std::string("cannot run gnuplot (") + std::strerror(spawned) +
             "; it comes with the Debian package gnuplot-nox, see tools/setup)",
         "");
  }
  const bool written = WriteAll(script_pipe[1], script);
  close(script_pipe[1]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const std::string said = ReadAll(output.get());
  if (WIFSIGNALED(status))
    fail("gnuplot was killed by signal " + std::to_string(WTERMSIG(status)), said);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    fail("gnuplot failed (exit status " + std::to_string(WEXITSTATUS(status)) + ")",
         said);
  }
  if (!written) fail("gnuplot stopped reading its script", said);
  struct stat info;
  if (stat(png_path.c_str(), &info) != 0 || info.st_size == 0) {
    fail("gnuplot wrote no image to " + png_path, said);
  }
}

}  // namespace vahf::report
