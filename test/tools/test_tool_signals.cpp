// The signal fuzz (issue 28): every batch tool, run on a small job, gets SIGINT or SIGTERM at a
// seeded random moment after its stop handler is in place, as a user's Ctrl-C or a scheduler's
// kill would come. Wherever the signal lands (before the first unit of work, mid-way, after the
// last), the tool must exit 0 (it had finished) or 128 + the signal with a message naming what it
// kept, and every file under an output's final name must be whole: no .part file nor unfinished
// bag left, every CSV whole rows under its header, every JSON parsed, every PNG complete. The
// delay only picks the moment: a loaded machine changes the counts, never the verdict.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "program_run.hpp"

namespace ari_social_sim::tools::test {
namespace {

namespace fs = std::filesystem;

const std::string kSource = ARI_SOURCE_DIR;
// Runs per tool, and the seed of the signals and delays: issue 28's.
constexpr int kRunsPerTool = 4;
constexpr uint64_t kSeed = 28;

// One tool's small job.
struct ToolJob {
  std::string name;
  std::string program;
  std::string arguments;  // shell syntax; {dir} stands for the run's output folder
  // What a finished run leaves in {dir}, under final names, not empty.
  std::vector<std::string> outputs;
  // The progress file a stopped run keeps in {dir} for --resume ("" when the tool has none).
  std::string journal;
  // The signal goes a uniform random time in [0, this] after the handler is in place: about the
  // job's length on a 2-core machine, so that some runs are stopped and some finish.
  double longest_delay_s;
  bool output_is_stdout{false};  // standard output goes to {dir}/stdout.csv, the tool's output
};

// Checks every file under a run's folder (argv[1]) by its kind and prints `files N`, the number
// checked, with each problem on standard error and exit status 1. argv[2]: the progress file a
// stopped run may keep, not checked ("-" for none). A bag is whole once closed: rosbag writes its
// index position, 0 until then, in the header record after the version line.
constexpr const char* kCheckScript = R"PY(
import csv, io, json, os, struct, sys, zlib, yaml
folder, journal = sys.argv[1], sys.argv[2]
problems = []
def png_whole(data):
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        return False
    at = 8
    while at + 12 <= len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        end = at + 8 + length
        crc = struct.pack(">I", zlib.crc32(data[at + 4:end]))
        if end + 4 > len(data) or data[end:end + 4] != crc:
            return False
        at += 12 + length
        if kind == b"IEND":
            return at == len(data)
    return False
def csv_whole(text, may_be_empty):
    if text == "":
        return may_be_empty
    rows = list(csv.reader(io.StringIO(text)))
    return text.endswith("\n") and len(rows) >= 1 and all(len(r) == len(rows[0]) for r in rows)
def bag_whole(data):
    header_at = len(b"#ROSBAG V2.0\n")
    if data[:header_at] != b"#ROSBAG V2.0\n":
        return False
    (length,) = struct.unpack("<I", data[header_at:header_at + 4])
    fields, at = {}, header_at + 4
    while at < header_at + 4 + length:
        (size,) = struct.unpack("<I", data[at:at + 4])
        name, _, value = data[at + 4:at + 4 + size].partition(b"=")
        fields[name] = value
        at += 4 + size
    index_pos = struct.unpack("<Q", fields.get(b"index_pos", b"\0" * 8))[0]
    return 0 < index_pos < len(data)
def whole(name, data):
    if name.endswith(".png"):
        return png_whole(data)
    if name.endswith(".csv"):
        return csv_whole(data.decode(), name == "stdout.csv")
    if name.endswith(".json"):
        json.loads(data)
        return True
    if name.endswith(".jsonl"):
        lines = data.decode().split("\n")
        for line in lines[:-1]:
            json.loads(line)
        return lines[-1] == "" and len(lines) > 1
    if name.endswith(".yaml"):
        return isinstance(yaml.safe_load(data), dict)
    if name.endswith(".bag"):
        return bag_whole(data)
    problems.append(name + ": a file of unknown kind")
    return True
count = 0
for root, _, names in os.walk(folder):
    for name in names:
        path = os.path.relpath(os.path.join(root, name), folder)
        if path == journal:
            continue
        if path.endswith(".part") or path.endswith(".active"):
            problems.append(path + ": left behind")
            continue
        with open(os.path.join(folder, path), "rb") as f:
            data = f.read()
        count += 1
        try:
            if not whole(name, data):
                problems.append(path + ": not whole (%d bytes)" % len(data))
        except Exception as e:  # a parser's or a truncated structure's
            problems.append(path + ": does not parse: " + str(e)[:200])
for problem in problems:
    sys.stderr.write(problem + "\n")
print("files %d" % count)
sys.exit(1 if problems else 0)
)PY";

// Whether child `pid`, not yet waited for, has ended.
bool ended(pid_t pid) {
  siginfo_t info{};
  return waitid(P_PID, pid, &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid;
}

// Whether `pid` runs `program` (no longer the shell that execs it) and catches SIGINT and SIGTERM
// (the SigCgt mask of /proc/PID/status): its stop handler is in place.
bool handler_in_place(pid_t pid, const std::string& program) {
  const std::string proc = "/proc/" + std::to_string(pid);
  std::error_code error;
  if (fs::read_symlink(proc + "/exe", error) != fs::canonical(program)) {
    return false;
  }
  std::ifstream status(proc + "/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("SigCgt:", 0) == 0) {
      const unsigned long long caught = std::stoull(line.substr(7), nullptr, 16);
      const unsigned long long wanted = (1ull << (SIGINT - 1)) | (1ull << (SIGTERM - 1));
      return (caught & wanted) == wanted;
    }
  }
  return false;
}

std::string with_dir(std::string text, const std::string& dir) {
  for (size_t at = text.find("{dir}"); at != std::string::npos;
       at = text.find("{dir}", at + dir.size())) {
    text.replace(at, 5, dir);
  }
  return text;
}

const char* signal_name(int signal) {
  return signal == SIGINT ? "SIGINT" : "SIGTERM";
}

// What one run did.
struct RunOutcome {
  bool handler_seen{false};  // the tool was seen running with its handler in place
  bool sent{false};          // the signal went to a running tool
  bool stopped{false};       // exit 128 + the signal
  bool finished{false};      // exit 0
  int files{0};              // files checked whole in its folder
};

// A synthetic F-formation table, big enough for detect_groups to take a while: `frames` frames of
// two pairs and a person alone.
std::string features_file(int frames) {
  const std::string path = ::testing::TempDir() + "tool_signals_features.csv";
  std::ofstream out(path);
  out << "frame,person_id,x,y,theta\n";
  for (int f = 0; f < frames; ++f) {
    out << f << ",a,0,0,0\n" << f << ",b,1.2,0,3.141593\n" << f << ",c,4,0,0\n";
    out << f << ",d,4,1.2,-1.570796\n" << f << ",e,8,8,0\n";
  }
  return path;
}

// A synthetic MPGT corpus for fit_dialogue_model without the data set: `count` conversations, each
// a six-line exchange (test/dialogue/test_model_fitting.cpp's) said `repeats` times. Long files
// rather than many: the fit takes a while, creating them does not.
std::string corpus_dir(int count, int repeats) {
  const std::string dir = ::testing::TempDir() + "tool_signals_mpgt";
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (int i = 1; i <= count; ++i) {
    std::ofstream out(dir + "/convo" + std::to_string(i) + ".txt");
    for (int r = 0; r < repeats; ++r) {
      out << "ARI: Hello. # greet()\n"
             "LP: Where is the cafe? # request(location(cafe)) @ G(LP, go-to(cafe))\n"
             "ARI: Ground floor. # inform(location(cafe)) @ AG(LP, go-to(cafe))\n"
             "LP: Shall we go? # suggest(going-to(cafe))\n"
             "RC: Yes. # affirm()\n"
             "RC: Thank you. # thank()\n";
    }
  }
  return dir;
}

std::vector<ToolJob> tool_jobs() {
  const std::string world = kSource + "/worlds/hospital_waiting_room.yaml";
  return {
      {"run_episodes",
       ARI_RUN_EPISODES_BIN,
       "--scenario join_group --episodes 2 --seed 2 --out {dir}",
       {"join_group.csv", "join_group.settings.yaml", "join_group_2.bag", "join_group_3.bag"},
       "",
       1.5},
      {"export_dataset",
       ARI_EXPORT_DATASET_BIN,
       "--scenario join_group --episodes 2 --cameras torso --every 2 --out {dir}",
       {"annotations.json"},
       "annotations.json.active",
       2.5},
      {"nav_benchmark",
       ARI_NAV_BENCHMARK_BIN,
       "--episodes 2 --types pose --controllers social,baseline --csv {dir}/nav.csv",
       {"nav.csv"},
       "nav.csv.active",
       0.3},
      {"render_cameras",
       ARI_RENDER_CAMERAS_BIN,
       "--world " + world + " --out {dir}",
       {"camera_head.png", "camera_torso_depth.png", "camera_torso_rgb_mask.png"},
       "",
       1.6},
      {"detect_groups",
       ARI_DETECT_GROUPS_BIN,
       "--features " + features_file(100000) + " --stride 0.6 --mdl 0.8",
       {"stdout.csv"},
       "",
       1.3,
       /*output_is_stdout=*/true},
      {"dialogue_corpus",
       ARI_DIALOGUE_CORPUS_BIN,
       "--dialogues 3000 --seed 1 --out {dir}/corpus.jsonl",
       {"corpus.jsonl"},
       "",
       1.5},
      {"export_group_streams",
       ARI_EXPORT_GROUP_STREAMS_BIN,
       "--scenes 2 --seed 3 --seconds 10 --every 0.5 --out {dir}",
       {"features.csv", "groundtruth.csv", "frames.csv"},
       "",
       1.7},
      {"fit_dialogue_model",
       ARI_FIT_DIALOGUE_MODEL_BIN,
       "--corpus " + corpus_dir(100, 200) + " --out {dir}/model.yaml",
       {"model.yaml"},
       "",
       0.3},
  };
}

// Files under `dir` whole by their kind (kCheckScript); the count, or -1 after a failure.
int check_files(const std::string& dir, const std::string& journal) {
  const std::string script = ::testing::TempDir() + "tool_signals_check.py";
  std::ofstream(script) << kCheckScript;
  const ProgramRun check =
      run_program("/usr/bin/python3", script + " " + dir + " " + (journal.empty() ? "-" : journal));
  EXPECT_EQ(check.status, 0) << dir << ":\n" << check.err;
  int files = -1;
  return check.status == 0 && std::sscanf(check.out.c_str(), "files %d", &files) == 1 ? files : -1;
}

// Runs `job` once, sends `signal` `delay_s` after its handler is in place (unless it has ended by
// then) and checks its exit code, its message and its files.
RunOutcome run_once(const ToolJob& job, int run, int signal, double delay_s) {
  const std::string dir =
      ::testing::TempDir() + "tool_signals/" + job.name + "_" + std::to_string(run);
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string err = dir + ".stderr.txt";
  const std::string out = job.output_is_stdout ? dir + "/stdout.csv" : dir + ".stdout.txt";
  const pid_t pid = start_in_background(job.program, with_dir(job.arguments, dir), out, err);
  RunOutcome outcome;
  if (pid <= 0) {
    ADD_FAILURE() << job.name << ": cannot start";
    return outcome;
  }
  EXPECT_TRUE(wait_until([&] {
    outcome.handler_seen = handler_in_place(pid, job.program);
    return outcome.handler_seen || ended(pid);
  }));
  std::this_thread::sleep_for(std::chrono::duration<double>(delay_s));
  outcome.sent = !ended(pid) && kill(pid, signal) == 0;
  int raw = 0;
  EXPECT_EQ(waitpid(pid, &raw, 0), pid);
  const std::string message = read_all(err);
  // Killed by the signal: the handler missed it.
  EXPECT_TRUE(WIFEXITED(raw)) << job.name << " run " << run << ": ended by signal " << WTERMSIG(raw)
                              << "\n"
                              << message;
  const int code = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  outcome.finished = code == 0;
  outcome.stopped = outcome.sent && code == 128 + signal;
  EXPECT_TRUE(outcome.finished || outcome.stopped)
      << job.name << " run " << run << ": exit " << code << " after " << signal_name(signal) << "\n"
      << message;
  const std::string said = job.name + ": interrupted by " + signal_name(signal) + " after ";
  EXPECT_EQ(message.find(said) != std::string::npos, outcome.stopped) << message;
  for (const std::string& output : outcome.finished ? job.outputs : std::vector<std::string>{}) {
    EXPECT_GT(fs::exists(dir + "/" + output) ? fs::file_size(dir + "/" + output) : 0u, 0u)
        << job.name << " run " << run << ": " << output;
  }
  outcome.files = check_files(dir, outcome.stopped ? job.journal : "");
  return outcome;
}

// One tool's counts, for the table.
struct ToolCounts {
  int runs{0};
  int sigint{0};
  int sigterm{0};
  int sent{0};
  int handler_seen{0};
  int finished{0};
  int stopped{0};
  int files{0};
  double seconds{0.0};

  void add(const ToolCounts& other) {
    runs += other.runs;
    sigint += other.sigint;
    sigterm += other.sigterm;
    sent += other.sent;
    handler_seen += other.handler_seen;
    finished += other.finished;
    stopped += other.stopped;
    files += other.files;
    seconds += other.seconds;
  }
};

void print_row(const std::string& name, const ToolCounts& c) {
  std::printf("[ measured ] %-20s %4d %4d %6d %7d %4d %8d %7d %5d %7.1f\n", name.c_str(), c.runs,
              c.sent, c.sigint, c.sigterm, c.handler_seen, c.finished, c.stopped, c.files,
              c.seconds);
}

TEST(ToolSignals, EveryBatchToolStopsCleanlyWhereverTheSignalLands) {
  std::mt19937_64 rng(kSeed);
  std::printf(
      "[ measured ] signal fuzz, seed %llu, %d runs per tool; sent: signals that found the "
      "tool still running after the delay; seen: runs where its handler was seen in place; "
      "finished: exit 0; stopped: exit 130 or 143; files: outputs checked whole\n",
      static_cast<unsigned long long>(kSeed), kRunsPerTool);
  std::printf("[ measured ] %-20s runs sent SIGINT SIGTERM seen finished stopped files seconds\n",
              "tool");
  ToolCounts total;
  for (const ToolJob& job : tool_jobs()) {
    ToolCounts counts;
    const auto start = std::chrono::steady_clock::now();
    for (int run = 0; run < kRunsPerTool; ++run) {
      const int signal = std::bernoulli_distribution(0.5)(rng) ? SIGINT : SIGTERM;
      const double delay_s = std::uniform_real_distribution<double>(0.0, job.longest_delay_s)(rng);
      const RunOutcome outcome = run_once(job, run, signal, delay_s);
      ++counts.runs;
      counts.sent += outcome.sent ? 1 : 0;
      counts.handler_seen += outcome.handler_seen ? 1 : 0;
      counts.sigint += outcome.sent && signal == SIGINT ? 1 : 0;
      counts.sigterm += outcome.sent && signal == SIGTERM ? 1 : 0;
      counts.finished += outcome.finished ? 1 : 0;
      counts.stopped += outcome.stopped ? 1 : 0;
      counts.files += std::max(outcome.files, 0);
    }
    counts.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    print_row(job.name, counts);
    // A tool that never installs its handler would only ever be waited for, finishing each run
    // and passing; each job works for a tenth of a second or more with its handler in place, so
    // that polling every 5 ms sees it in some run.
    EXPECT_GT(counts.handler_seen, 0) << job.name << ": never seen with its stop handler in place";
    total.add(counts);
  }
  print_row("total", total);
}

}  // namespace
}  // namespace ari_social_sim::tools::test
