#include "tools/rgbd/run_command.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>

#include "io/errors.h"

extern char** environ;

namespace msp {
namespace rgbd {
namespace {

// The exit code of a shell whose child was ended by a signal.
constexpr int kSignalExitBase = 128;
constexpr mode_t kLogMode = 0644;

std::string LastLine(const std::string& path) {
  std::ifstream file(path);
  std::string line, last;
  while (std::getline(file, line)) {
    if (!line.empty()) last = line;
  }
  return last;
}

}  // namespace

int RunCommand(const std::vector<std::string>& argv, const std::string& log_path) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log_path.c_str(),
                                   O_WRONLY | O_CREAT | O_APPEND, kLogMode);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return WIFSIGNALED(status) ? kSignalExitBase + WTERMSIG(status) : -1;
}

void RunCommandOrThrow(const std::vector<std::string>& argv, const std::string& log_path) {
  const int rc = RunCommand(argv, log_path);
  if (rc == 0) return;
  std::string command = argv[0];
  if (argv.size() > 1) command += " " + argv[1];
  if (rc < 0) throw InputError("cannot run `" + argv[0] + "` (is it installed and on PATH?)");
  throw InputError("`" + command + "` failed with exit code " + std::to_string(rc) + " (log " +
                   log_path + "): " + LastLine(log_path));
}

}  // namespace rgbd
}  // namespace msp
