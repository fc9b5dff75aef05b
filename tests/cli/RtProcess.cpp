#include "RtProcess.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "TestFiles.h"

#ifndef RT_EXE
#error "RT_EXE must name the rt executable"
#endif

namespace rt::cli::test {

namespace {

std::vector<char*> argvOf(std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  return argv;
}

int exitCodeOf(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : -1; }

/// An unlinked temporary file to capture a stream.
int captureFile() {
  char name[] = "/tmp/rt-cli-test-XXXXXX";
  const int fd = ::mkstemp(name);
  if (fd < 0) throw std::runtime_error("mkstemp failed");
  ::unlink(name);
  return fd;
}

std::string readAll(int fd) {
  std::string s;
  ::lseek(fd, 0, SEEK_SET);
  char buf[4096];
  ssize_t n;
  while ((n = ::read(fd, buf, sizeof buf)) > 0) s.append(buf, static_cast<std::size_t>(n));
  return s;
}

}  // namespace

RtResult runRt(const std::vector<std::string>& args, const RtOptions& options) {
  std::vector<std::string> all{RT_EXE};
  all.insert(all.end(), args.begin(), args.end());
  return runProgram(all, options);
}

RtResult runProgram(const std::vector<std::string>& command, const RtOptions& options) {
  std::vector<std::string> all = command;
  std::vector<char*> argv = argvOf(all);
  const int outFd = captureFile(), errFd = captureFile();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::dup2(outFd, STDOUT_FILENO);
    ::dup2(errFd, STDERR_FILENO);
    if (!options.cwd.empty() && ::chdir(options.cwd.c_str()) != 0) ::_exit(126);
    if (!options.path.empty()) ::setenv("PATH", options.path.c_str(), 1);
    if (options.asUnprivileged && ::geteuid() == 0) {
      if (::setgid(65534) != 0 || ::setuid(65534) != 0) ::_exit(125);
    }
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  RtResult r{exitCodeOf(status), readAll(outFd), readAll(errFd)};
  ::close(outFd);
  ::close(errFd);
  return r;
}

RtChild::RtChild(const std::vector<std::string>& args)
    : RtChild(Program{[&] {
        std::vector<std::string> all{RT_EXE};
        all.insert(all.end(), args.begin(), args.end());
        return all;
      }()}) {}

RtChild::RtChild(const Program& program) {
  std::vector<std::string> all = program.argv;
  std::vector<char*> argv = argvOf(all);
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("pipe failed");
  pid_ = ::fork();
  if (pid_ == 0) {
    ::dup2(fds[1], STDERR_FILENO);
    ::close(fds[0]);
    ::close(fds[1]);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  ::close(fds[1]);
  errFd_ = fds[0];
}

RtChild::~RtChild() {
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    wait();
  }
  if (errFd_ >= 0) ::close(errFd_);
}

bool RtChild::waitForLine(const std::string& text) {
  for (;;) {
    if (err_.find(text, scanned_) != std::string::npos) return true;
    char buf[4096];
    const ssize_t n = ::read(errFd_, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    err_.append(buf, static_cast<std::size_t>(n));
  }
}

void RtChild::signal(int sig) { ::kill(pid_, sig); }

int RtChild::wait() {
  char buf[4096];
  ssize_t n;
  while ((n = ::read(errFd_, buf, sizeof buf)) > 0) err_.append(buf, static_cast<std::size_t>(n));
  int status = 0;
  ::waitpid(pid_, &status, 0);
  pid_ = -1;
  return exitCodeOf(status);
}

std::string freshDirectory(const std::string& name) {
  return std::filesystem::absolute(freshTestDirectory(name)).string();
}

}  // namespace rt::cli::test
