// Each method runs in a forked child process that inherits the mesh (copy-on-write) and sends back
// its timings and distances through a pipe. A crash, an exception, an exhausted memory or a hang then
// costs one row of the table instead of the whole benchmark, and solvers that keep threads or large
// caches start clean every time. Timings are medians of repetitions (machines here are shared).
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <exception>

#include "bench_geodesic.h"

namespace bake::bench {
namespace {

using Clock = std::chrono::steady_clock;

void writeAll(int fd, const void* data, std::size_t size) {
  const char* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t written = ::write(fd, bytes, size);
    if (written <= 0) _exit(3);
    bytes += written;
    size -= static_cast<std::size_t>(written);
  }
}

// Child side: 'O' seconds setup runs count distances..., or 'E' length message.
[[noreturn]] void childMain(int fd, const std::function<Measurement()>& job) {
  try {
    const Measurement m = job();
    const std::uint64_t count = m.distances.size();
    writeAll(fd, "O", 1);
    writeAll(fd, &m.seconds, sizeof m.seconds);
    writeAll(fd, &m.setupSeconds, sizeof m.setupSeconds);
    writeAll(fd, &m.runs, sizeof m.runs);
    writeAll(fd, &count, sizeof count);
    writeAll(fd, m.distances.data(), count * sizeof(double));
  } catch (const std::exception& error) {
    const std::string message = error.what();
    const std::uint64_t length = message.size();
    writeAll(fd, "E", 1);
    writeAll(fd, &length, sizeof length);
    writeAll(fd, message.data(), length);
  }
  ::close(fd);
  _exit(0);
}

// Reads everything the child writes, or gives up at the deadline. Returns false on time-out.
bool readUntilClosed(int fd, Clock::time_point deadline, std::string& buffer) {
  char chunk[1 << 16];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return false;
    pollfd pfd{fd, POLLIN, 0};
    const int ready = ::poll(&pfd, 1, static_cast<int>(std::min<long long>(left, 1'000'000)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    const ssize_t got = ::read(fd, chunk, sizeof chunk);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return true;
    buffer.append(chunk, static_cast<std::size_t>(got));
  }
}

template <class T>
bool take(const std::string& buffer, std::size_t& at, T* out, std::size_t count = 1) {
  if (at + count * sizeof(T) > buffer.size()) return false;
  std::memcpy(out, buffer.data() + at, count * sizeof(T));
  at += count * sizeof(T);
  return true;
}

RunOutcome parse(const std::string& buffer) {
  RunOutcome outcome;
  std::size_t at = 1;
  std::uint64_t count = 0;
  if (!buffer.empty() && buffer[0] == 'E' && take(buffer, at, &count) && at + count <= buffer.size()) {
    outcome.error = buffer.substr(at, count);
    return outcome;
  }
  Measurement& m = outcome.measurement;
  if (buffer.empty() || buffer[0] != 'O' || !take(buffer, at, &m.seconds) || !take(buffer, at, &m.setupSeconds) ||
      !take(buffer, at, &m.runs) || !take(buffer, at, &count)) {
    outcome.error = "the run sent back an incomplete result";
    return outcome;
  }
  m.distances.resize(count);
  if (!take(buffer, at, m.distances.data(), count)) {
    outcome.error = "the run sent back an incomplete result";
    return outcome;
  }
  outcome.ok = true;
  return outcome;
}

}  // namespace

RunOutcome runIsolated(const std::function<Measurement()>& job, double timeoutSeconds, double memoryLimitBytes) {
  int fds[2];
  if (::pipe(fds) != 0) return {false, "pipe failed", {}};
  const pid_t pid = ::fork();
  if (pid < 0) return {false, "fork failed", {}};
  if (pid == 0) {
    ::close(fds[0]);
    if (memoryLimitBytes > 0) {
      const rlimit limit{static_cast<rlim_t>(memoryLimitBytes), static_cast<rlim_t>(memoryLimitBytes)};
      ::setrlimit(RLIMIT_AS, &limit);  // running out is a std::bad_alloc (or a crash): a failed row
    }
    childMain(fds[1], job);
  }
  ::close(fds[1]);
  std::string buffer;
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeoutSeconds));
  const bool finished = readUntilClosed(fds[0], deadline, buffer);
  ::close(fds[0]);
  if (!finished) ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (!finished) return {false, "timed out after " + std::to_string(int(timeoutSeconds)) + " s", {}};
  if (WIFSIGNALED(status))
    return {false, std::string("crashed: ") + strsignal(WTERMSIG(status)), {}};
  return parse(buffer);
}

bool RepeatRule::again(int done, double elapsedSeconds) const {
  if (elapsedSeconds > budgetSeconds) return false;
  if (done < repeats) return true;
  return elapsedSeconds < minSeconds && done < kMaxRepeats;
}

double medianSeconds(const std::function<void()>& field, const RepeatRule& rule, int* runs) {
  std::vector<double> times;
  const auto start = Clock::now();
  do {
    const auto before = Clock::now();
    field();
    times.push_back(std::chrono::duration<double>(Clock::now() - before).count());
  } while (rule.again(static_cast<int>(times.size()), std::chrono::duration<double>(Clock::now() - start).count()));
  if (runs) *runs = static_cast<int>(times.size());
  return medianOf(std::move(times));
}

double medianOf(std::vector<double> times) {
  if (times.empty()) return 0;
  std::sort(times.begin(), times.end());
  const std::size_t n = times.size();
  return n % 2 ? times[n / 2] : 0.5 * (times[n / 2 - 1] + times[n / 2]);
}

}  // namespace bake::bench
