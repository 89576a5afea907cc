// Ctrl-C and progress on the command line (issue 18): a long run that gets SIGINT stops at the
// run's next poll with exit 130 and one line on stderr, and writes nothing — no --output file,
// no temporary beside it, nothing on stdout; the same for a case run and a sweep. On a terminal
// (a pseudo-terminal here) a run of over a second draws the progress line on stderr.
//
// "At the next poll" is measured in the CPU time the process spends after the signal (what it
// did), not in wall time (what the machine let it do): a loaded machine stretches the wall time
// from the signal to the exit without bound, but not the work done in it. The runs here are
// seconds to tens of seconds of CPU each; a run that ignored the flag until its end would spend
// nearly all of that after the signal. The wall time is bounded only as a guard against a hang.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <pty.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "../read_text.hpp"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// The thesis ring of issue 18 by the finite-difference sweep with 10× its node cap: 25 s of work.
const std::vector<std::string> kLongRing = {
    "ring",  "--inner-radius", "4.72",   "--outer-radius", "10",    "--thickness",
    "1",     "--E-r",          "10GPa",  "--E-phi",        "40GPa", "--G",
    "4GPa",  "--nu-phi-r",     "0.28",   "--gap",          "0.02",  "--method",
    "sweep", "--nodes",        "200000", "--allow-large"};

// CPU time [s] a run may spend from the SIGINT to its exit: its next poll (a ring harmonic's
// row, ~0.1 s of CPU; a simulation's step, well under 1 ms) on each of its threads, the unwinding
// and the exit (freeing the 200000-node ring's memory; under a sanitizer, its exit checks). The
// runs below have 8 s or more of CPU still to do when the signal comes.
constexpr double kCpuAfterSignal = 2.0;
// Wall time [s] from the SIGINT after which the run counts as hung and is killed (a guard only:
// the assertions are on what the process did, not on how fast a loaded machine let it).
constexpr double kHangGuard = 120.0;

struct Stopped {
  int status = -1;           // exit status, -1 when ended by a signal
  int signal = 0;            // the signal that ended it, if one did
  std::string out, err;      // stdout; stderr (or what the terminal showed)
  double cpu_at_signal = 0;  // [s] user + system CPU time of the process when SIGINT was sent
  double cpu_after = -1;     // [s] CPU time it spent from the SIGINT to its exit (-1: unknown)
  bool hung = false;         // still running kHangGuard s after the SIGINT (then killed)
};

// User + system CPU time [s] of the running process `pid`, all its threads (Linux: fields 14 and
// 15 of /proc/<pid>/stat, in clock ticks); -1 if it cannot be read.
double cpu_seconds(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  std::getline(stat, text);
  const std::size_t close = text.rfind(')');  // the command name may hold spaces
  if (close == std::string::npos) return -1.0;
  std::istringstream fields(text.substr(close + 1));
  std::string field;
  unsigned long long utime = 0, stime = 0;
  for (int k = 3; k <= 15 && fields >> field; ++k) {
    if (k == 14) utime = std::stoull(field);
    if (k == 15) stime = std::stoull(field);
  }
  return static_cast<double>(utime + stime) / static_cast<double>(::sysconf(_SC_CLK_TCK));
}

double seconds_of(const timeval& t) {
  return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
}

// A fresh, empty folder for one test's files.
fs::path folder(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("catena_interrupt_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// True once process `pid` catches SIGINT (Linux: the SigCgt mask of /proc/<pid>/status).
bool catches_sigint(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("SigCgt:", 0) != 0) continue;
    const unsigned long long mask = std::stoull(line.substr(7), nullptr, 16);
    return (mask >> (SIGINT - 1)) & 1ULL;
  }
  return false;
}

// Runs catena with `args`, stdout and stderr to files in `dir` (stderr to a pseudo-terminal when
// `terminal`), sends SIGINT once it catches SIGINT and `wait` has passed (on a terminal: once the
// progress line shows, or after `wait` at most), and waits for it to end.
Stopped interrupt(const std::vector<std::string>& args, const fs::path& dir,
                  std::chrono::milliseconds wait, bool terminal = false) {
  const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  int master = -1, slave = -1;
  if (terminal && ::openpty(&master, &slave, nullptr, nullptr, nullptr) != 0) return {};
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = terminal ? slave : ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(o, STDOUT_FILENO);
    ::dup2(e, STDERR_FILENO);
    std::vector<char*> argv;
    std::string program = CATENA_CLI;
    argv.push_back(program.data());
    std::vector<std::string> copy = args;
    for (std::string& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(program.c_str(), argv.data());
    ::_exit(127);
  }
  if (terminal) ::close(slave);
  std::string shown;
  std::mutex mutex;
  // the terminal's side: read what the run draws while it runs (the pty would fill otherwise)
  std::thread reader;
  if (terminal) {
    reader = std::thread([master, &shown, &mutex] {
      char buffer[4096];
      for (;;) {
        const ssize_t n = ::read(master, buffer, sizeof buffer);
        if (n <= 0) break;  // EIO once the child has closed its side
        const std::lock_guard<std::mutex> lock(mutex);
        shown.append(buffer, static_cast<std::size_t>(n));
      }
    });
  }
  // SIGINT only after the run has installed its handler: a slow start (a sanitizer build, a
  // loaded machine) would otherwise take the default action and end the process by the signal.
  // Then `wait` more, so that the signal lands in the middle of the work.
  const auto give_up = Clock::now() + std::chrono::seconds(20);
  while (!catches_sigint(pid) && Clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const auto deadline = Clock::now() + wait;
  while (Clock::now() < deadline) {
    if (terminal) {
      const std::lock_guard<std::mutex> lock(mutex);
      if (shown.find(" s") != std::string::npos) break;  // a whole progress line is drawn
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  Stopped r;
  r.cpu_at_signal = cpu_seconds(pid);
  const auto sent = Clock::now();
  ::kill(pid, SIGINT);
  int status = 0;
  rusage usage{};
  // the hang guard: poll for the exit, kill the run if it outlives the guard
  const auto hang = sent + std::chrono::duration<double>(kHangGuard);
  for (;;) {
    const pid_t done = ::wait4(pid, &status, WNOHANG, &usage);
    if (done == pid || done < 0) break;
    if (Clock::now() > hang) {
      r.hung = true;
      ::kill(pid, SIGKILL);
      ::wait4(pid, &status, 0, &usage);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  // the whole run's CPU time (all threads) less what it had spent when the signal was sent
  if (r.cpu_at_signal >= 0)
    r.cpu_after = seconds_of(usage.ru_utime) + seconds_of(usage.ru_stime) - r.cpu_at_signal;
  if (terminal) {
    reader.join();
    ::close(master);
  }
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  r.out = read_text(out);
  r.err = terminal ? shown : read_text(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

std::vector<std::string> files_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir))
    names.push_back(entry.path().filename().string());
  return names;
}

const char* kMessage = "catena: interrupted (Ctrl-C); nothing was written\n";

// It stopped at its next poll: it ended by itself (not by the hang guard) and spent less than a
// poll's CPU time after the signal — far less than the work it had left.
void expect_stopped_at_next_poll(const Stopped& r, const std::string& what) {
  std::printf("%s: %.3f s of CPU before the SIGINT, %.3f s after it\n", what.c_str(),
              r.cpu_at_signal, r.cpu_after);
  EXPECT_FALSE(r.hung) << what << ": still running " << kHangGuard << " s after the SIGINT";
  EXPECT_GE(r.cpu_after, 0.0) << what << ": the CPU time was not read";
  EXPECT_LT(r.cpu_after, kCpuAfterSignal)
      << what << ": " << r.cpu_after << " s of CPU after the SIGINT (" << r.cpu_at_signal
      << " s before it)";
}

TEST(InterruptCli, CtrlCStopsALongAnalysisWithStatus130AndWritesNoOutputNorTemporary) {
  const fs::path dir = folder("analysis");
  std::vector<std::string> args = kLongRing;
  args.insert(args.end(), {"--format", "json", "--output", (dir / "ring.json").string(), "--csv",
                           (dir / "ring.csv").string()});
  const Stopped r = interrupt(args, dir, std::chrono::milliseconds(400));
  EXPECT_EQ(r.signal, 0);
  EXPECT_EQ(r.status, 130) << r.err;
  EXPECT_EQ(r.err, kMessage);
  EXPECT_EQ(r.out, "");
  expect_stopped_at_next_poll(r, "ring");  // at the next poll, not after the 25 s of work
  EXPECT_EQ(files_in(dir), std::vector<std::string>{});  // no ring.json, no temporary
  fs::remove_all(dir);
}

TEST(InterruptCli, CtrlCStopsACaseRunAndASweepAlike) {
  const fs::path dir = folder("case");
  const fs::path toml = dir / "ring.toml";
  {
    std::ofstream case_file(toml);
    case_file << "title = \"long ring\"\n[chain]\ntype = \"composite-link\"\n"
                 "[analyses.ring]\ninner_radius = 4.72\nouter_radius = 10\nthickness = 1\n"
                 "E_r = \"10GPa\"\nE_phi = \"40GPa\"\nG = \"4GPa\"\nnu_phi_r = 0.28\n"
                 "gap = 0.02\nmethod = \"sweep\"\nnodes = 200000\nallow_large = true\n";
  }
  const std::string json = (dir / "out.json").string();
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"run", toml.string(), "--output", json},
        std::vector<std::string>{"report", toml.string(), "--output", json, "--format", "json"},
        std::vector<std::string>{"sweep", toml.string(), "--grid", "gap=0.02,0.021,0.022",
                                 "--threads", "2", "--output", json}}) {
    const Stopped r = interrupt(args, dir, std::chrono::milliseconds(400));
    EXPECT_EQ(r.signal, 0) << args[0];
    EXPECT_EQ(r.status, 130) << args[0] << ": " << r.err;
    EXPECT_EQ(r.err, kMessage) << args[0];
    EXPECT_EQ(r.out, "") << args[0];
    expect_stopped_at_next_poll(r, args[0]);
    EXPECT_EQ(files_in(dir), std::vector<std::string>{"ring.toml"}) << args[0];
  }
  fs::remove_all(dir);
}

// A sweep of simulations (issue 21): two 60 s runs of the 12B drive, each ~10 s of work, stop at
// the steps' next poll like any other sweep's points.
TEST(InterruptCli, CtrlCStopsASweepOfSimulations) {
  const fs::path dir = folder("dynamics");
  const std::string csv = (dir / "out.csv").string();
  const Stopped r = interrupt({"sweep", std::string(CATENA_EXAMPLES_DIR) + "/dynamics_12B.toml",
                               "--grid", "duration=60s,61s", "--grid",
                               "dynamics.output_interval=1ms", "--threads", "2", "--output", csv},
                              dir, std::chrono::milliseconds(400));
  EXPECT_EQ(r.signal, 0);
  EXPECT_EQ(r.status, 130) << r.err;
  EXPECT_EQ(r.err, kMessage);
  EXPECT_EQ(r.out, "");
  expect_stopped_at_next_poll(r, "sweep of simulations");
  EXPECT_EQ(files_in(dir), std::vector<std::string>{});
  fs::remove_all(dir);
}

TEST(InterruptCli, OnATerminalALongRunDrawsItsProgressLineOnStderr) {
  const fs::path dir = folder("terminal");
  std::vector<std::string> args = kLongRing;
  args.insert(args.end(), {"--format", "json"});
  // SIGINT once the line shows (after the run's first second), 2.8 s at most
  const Stopped r = interrupt(args, dir, std::chrono::milliseconds(2800), true);
  EXPECT_EQ(r.status, 130) << r.err;
  // "\rcatena ring [#.......] 9/191 harmonics, 1 s", redrawn in place, then the message
  const std::size_t line = r.err.find("\rcatena ring [");
  ASSERT_NE(line, std::string::npos) << r.err;
  const std::size_t unit = r.err.find("/191 harmonics, ", line);
  ASSERT_NE(unit, std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" s", unit), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("catena: interrupted (Ctrl-C); nothing was written"), std::string::npos)
      << r.err;
  EXPECT_EQ(r.out, "");  // the JSON never started
  fs::remove_all(dir);
}

TEST(InterruptCli, OffATerminalNoProgressIsDrawn) {
  const fs::path dir = folder("pipe");
  std::vector<std::string> args = kLongRing;
  const Stopped r = interrupt(args, dir, std::chrono::milliseconds(1300));
  EXPECT_EQ(r.status, 130) << r.err;
  EXPECT_EQ(r.err, kMessage);  // nothing but the message: no bar in a file
  fs::remove_all(dir);
}

}  // namespace
