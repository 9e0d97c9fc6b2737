// taa-farm submit: a shot as a Slurm array job, or the job text of another scheduler
// (farm/verbs.h).
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "farm/farm_errors.h"
#include "farm/shot.h"
#include "farm/task_commands.h"
#include "farm/verbs.h"

extern char** environ;

namespace taa::farm {
namespace {

namespace fs = std::filesystem;

// Runs `sbatch --parsable` with `script` on its standard input; returns what it printed on
// stdout (stderr goes to ours). Throws taa::Error when it cannot run or fails.
std::string runSbatch(const std::string& script) {
  int input[2], output[2];
  if (::pipe(input) != 0 || ::pipe(output) != 0) {
    throw Error(std::string("cannot create a pipe for sbatch: ") + std::strerror(errno));
  }
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_adddup2(&files, input[0], 0);
  posix_spawn_file_actions_adddup2(&files, output[1], 1);
  for (int fd : {input[0], input[1], output[0], output[1]}) {
    posix_spawn_file_actions_addclose(&files, fd);
  }
  char sbatch[] = "sbatch", parsable[] = "--parsable";
  char* argv[] = {sbatch, parsable, nullptr};
  pid_t pid = 0;
  const int failed = posix_spawnp(&pid, "sbatch", &files, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&files);
  ::close(input[0]);
  ::close(output[1]);
  if (failed != 0) {
    ::close(input[1]);
    ::close(output[0]);
    throw Error(std::string("cannot run sbatch (is Slurm's client installed and on PATH?): ") +
                std::strerror(failed));
  }
  // Scripts are small: the pipe takes all of it before sbatch answers. An sbatch that exits
  // early must not end taa-farm with SIGPIPE: its exit status says why.
  struct sigaction ignore {}, previous {};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  ::sigaction(SIGPIPE, &ignore, &previous);
  for (std::size_t sent = 0; sent < script.size();) {
    const ssize_t n = ::write(input[1], script.data() + sent, script.size() - sent);
    if (n <= 0 && errno == EINTR) continue;
    if (n <= 0) break;
    sent += std::size_t(n);
  }
  ::close(input[1]);
  ::sigaction(SIGPIPE, &previous, nullptr);
  std::string printed;
  char buffer[4096];
  for (ssize_t n; (n = ::read(output[0], buffer, sizeof buffer)) > 0;) {
    printed.append(buffer, std::size_t(n));
  }
  ::close(output[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw Error("sbatch failed (exit status " +
                std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
                "); its message is above");
  }
  return printed;
}

std::string thisExecutable() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw Error("cannot find taa-farm's own path (/proc/self/exe): " + ec.message());
  return self.string();
}

}  // namespace

int submitShot(const FarmArguments& args) {
  const Shot shot = loadShot(args.taatoolArgs);
  const TaskCommand task =
      taskCommandOf(args, shot, thisExecutable(), fs::current_path().string());
  if (args.scheduler == Scheduler::OpenCue) {
    std::cout << openCueLayerText(task);
    return 0;
  }
  if (args.scheduler == Scheduler::Deadline) {
    std::cout << deadlineJobText(task);
    return 0;
  }
  SlurmOptions slurm = args.slurm;
  if (!slurm.logDir.empty()) slurm.logDir = fs::absolute(slurm.logDir).lexically_normal().string();
  const std::string script = slurmArrayScript(task, slurm);
  if (args.dryRun) {
    std::cout << script;
    return 0;
  }
  if (!slurm.logDir.empty()) fs::create_directories(slurm.logDir);
  std::string jobId = runSbatch(script);
  jobId = jobId.substr(0, jobId.find_first_of(";\n"));  // "id[;cluster]"
  if (jobId.empty()) throw Error("sbatch printed no job id");
  std::cout << jobId << std::endl;
  std::cerr << "taa-farm submit: job " << jobId << ", " << task.chunkCount << " task(s) of "
            << task.chunkSize << " frame(s) over " << task.framesText << "; logs "
            << (slurm.logDir.empty() ? task.workingFolder : slurm.logDir)
            << "/taa-farm-" << jobId << "_<task>.log; check with taa-farm status" << std::endl;
  return 0;
}

}  // namespace taa::farm
