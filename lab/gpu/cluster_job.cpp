#include "lab/gpu/cluster_job.h"

#include "atmosphere/reference/path_budget.h"
#include "core/error.h"
#include "lab/reference_share.h"
#include "lab/scene.h"
#include "render/capture_shares.h"
#include "sim/flight_script.h"
#include "terrain/ground.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>

namespace planet {

namespace {

// A command line's "--key value" and "--key=value" options (the last of
// each), and where they are.
struct CommandLine {
  std::vector<std::string> args;
  std::map<std::string, std::string> options;

  explicit CommandLine(std::vector<std::string> words) : args(std::move(words)) {
    for (size_t i = 1; i < args.size(); ++i) {
      const std::string& word = args[i];
      if (word.rfind("--", 0) != 0) continue;
      size_t eq = word.find('=');
      if (eq != std::string::npos) {
        options[word.substr(0, eq)] = word.substr(eq + 1);
      } else if (i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0) {
        options[word] = args[i + 1];
      } else {
        options[word] = "";
      }
    }
  }
  std::optional<std::string> get(const std::string& key) const {
    auto it = options.find(key);
    if (it == options.end()) return std::nullopt;
    return it->second;
  }
};

// A name a scheduler and Kubernetes both take: lower case letters, digits
// and '-', at most 52 characters (room for Kubernetes' "-merge" and pod
// suffixes within its 63).
std::string job_name(const std::string& text) {
  std::string out;
  for (char c : text) {
    bool ok = std::isalnum(static_cast<unsigned char>(c));
    out += ok ? char(std::tolower(static_cast<unsigned char>(c))) : '-';
  }
  out.erase(
      std::unique(out.begin(), out.end(), [](char a, char b) { return a == '-' && b == '-'; }),
      out.end());
  if (out.size() > 52) out.resize(52);
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out;
}

// A word as the shell reads it back: in single quotes unless plain.
std::string shell_word(const std::string& word) {
  bool plain = !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) ||
           std::string("/._-=,:+@%").find(c) != std::string::npos;
  });
  if (plain) return word;
  std::string out = "'";
  for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string shell_words(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : " ") + shell_word(w);
  return out;
}

}  // namespace

ClusterJob plan_cluster_job(const std::vector<std::string>& args, int tasks) {
  if (args.empty()) {
    throw InputError("cluster: name the command to split: reference ... or capture ...");
  }
  if (tasks < 1 || tasks > 65536) {
    throw InputError(fmt::format("cluster: --tasks {} is outside 1 to 65536", tasks));
  }
  CommandLine line(args);
  const std::string& command = args.front();
  for (const char* own : {"--shard", "--merge", "--frames", "--list"}) {
    if (line.get(own)) {
      throw InputError(
          fmt::format("cluster: {} {}: the job gives each task its own --shard "
                      "and merges; leave {} out",
                      command, own, own));
    }
  }
  ClusterJob job;
  job.tasks = tasks;
  job.command = args;
  if (command == "reference") {
    std::optional<std::string> scene_name = line.get("--scene"), out = line.get("--out");
    if (!scene_name || !out || out->empty()) {
      throw InputError("cluster: reference needs --scene and --out, as when run at once");
    }
    Scene scene = find_scene(*scene_name);
    if (auto spp = line.get("--spp")) PathBudget::parse(*spp);
    if (auto mode = line.get("--mode")) parse_reference_mode(*mode);
    std::filesystem::path shares = reference_shares_dir(*out);
    job.merge = {"reference", "--merge", shares.string(), "--out", *out};
    job.share_done = shell_word(shares.string()) + fmt::format("/share-*-of-{}.sums", tasks);
    job.name = job_name("planet-reference-" + scene.name);
  } else if (command == "capture") {
    std::optional<std::string> flight = line.get("--flight");
    if (!flight || flight->empty()) throw InputError("cluster: capture needs --flight");
    FlightScript script = load_flight_script(*flight, terrain_ground());
    if (tasks > script.frame_count()) {
      throw InputError(fmt::format("cluster: --tasks {}: {} has {} frames, too few for {} shares",
                                   tasks, *flight, script.frame_count(), tasks));
    }
    std::string out =
        line.get("--out").value_or((std::filesystem::path("out") / script.name).string());
    if (!line.get("--out")) job.command.insert(job.command.end(), {"--out", out});
    std::filesystem::path shares = capture_shares_dir(out);
    job.merge = {"capture", "--merge", shares.string(), "--out", out};
    job.share_done =
        shell_word(shares.string()) + fmt::format("/share-*-of-{}/capture.json", tasks);
    job.name = job_name("planet-capture-" + script.name);
  } else {
    throw InputError(
        fmt::format("cluster: '{}' is not split into shares: reference and "
                    "capture are",
                    command));
  }
  return job;
}

std::string slurm_job_script(const ClusterJob& job) {
  std::string extra;
  if (!job.time_limit.empty()) extra += fmt::format("#SBATCH --time={}\n", job.time_limit);
  if (!job.partition.empty()) extra += fmt::format("#SBATCH --partition={}\n", job.partition);
  std::string merge_extra;
  if (!job.time_limit.empty()) merge_extra += " --time=" + shell_word(job.time_limit);
  if (!job.partition.empty()) merge_extra += " --partition=" + shell_word(job.partition);
  return fmt::format(
      R"SH(#!/bin/bash
# planet {command} on {tasks} tasks of a Slurm job array, then one merge.
# Submit with: bash THIS_FILE   (where sbatch works, as on a login node)
# It queues the array, then the merge job {name}-merge, which Slurm
# holds until every task has ended well (afterok): the tasks themselves
# queue nothing, so the compute nodes need no sbatch. Task K runs the
# command with --shard K/{tasks}; the merge puts the shares together into
# the output, byte for byte the run made on one machine. Rerun failed
# tasks with `bash THIS_FILE K[,K...]`: they and a new merge are queued.
# The merge by hand:
#   {program} {merge_line}
#SBATCH --job-name={name}
#SBATCH --array=0-{last}
#SBATCH --cpus-per-task={cpus}
#SBATCH --chdir={workdir}
#SBATCH --output={name}-%A_%a.out
{extra}set -euo pipefail
planet={program}
share=("$planet" {share_args})
merge=("$planet" {merge_args})
if [ "${{1:-}}" = --task ]; then
  exec "${{share[@]}}" --shard "$SLURM_ARRAY_TASK_ID/{tasks}"
fi
if [ -n "${{SLURM_ARRAY_TASK_ID:-}}" ]; then
  echo "planet: $0 queues its array and merge itself: run it with bash, not sbatch" >&2
  exit 2
fi
tasks="${{1:-0-{last}}}"
if ! [[ "$tasks" =~ ^[0-9]+(-[0-9]+)?(,[0-9]+(-[0-9]+)?)*$ ]]; then
  echo "planet: $0: '$tasks' is not a list of tasks (K, K-L or K,L,...) of 0-{last}" >&2
  exit 2
fi
array_job=$(sbatch --parsable --array="$tasks" "$0" --task)
array_job=${{array_job%%;*}}  # "id;cluster" on a federation
merge_job=$(sbatch --parsable --job-name={name}-merge --chdir={workdir} \
  --output={name}-merge-%j.out --cpus-per-task=1{merge_extra} \
  --dependency=afterok:"$array_job" --kill-on-invalid-dep=yes \
  --wrap="$(printf '%q ' "${{merge[@]}}")")
merge_job=${{merge_job%%;*}}
echo "planet: job array $array_job (tasks $tasks) and merge job $merge_job, which waits for it"
)SH",
      fmt::arg("command", job.command.front()), fmt::arg("tasks", job.tasks),
      fmt::arg("name", job.name), fmt::arg("last", job.tasks - 1),
      fmt::arg("cpus", job.cpus_per_task), fmt::arg("workdir", shell_word(job.workdir.string())),
      fmt::arg("extra", extra), fmt::arg("program", shell_word(job.program)),
      fmt::arg("share_args", shell_words(job.command)),
      fmt::arg("merge_args", shell_words(job.merge)), fmt::arg("merge_extra", merge_extra),
      fmt::arg("merge_line", shell_words(job.merge)));
}

std::string kubernetes_manifest(const ClusterJob& job) {
  auto quoted = [](const std::string& s) { return nlohmann::json(s).dump(); };
  std::string share_command =
      fmt::format("exec {} {} --shard \"$JOB_COMPLETION_INDEX/{}\"", shell_word(job.program),
                  shell_words(job.command), job.tasks);
  std::string wait_command = fmt::format(
      "until [ \"$(ls -d {} 2>/dev/null | wc -l)\" -ge {} ]; do "
      "echo \"planet: $(ls -d {} 2>/dev/null | wc -l) of {} shares done\"; sleep 10; done",
      job.share_done, job.tasks, job.share_done, job.tasks);
  std::string merge_command =
      fmt::format("exec {} {}", shell_word(job.program), shell_words(job.merge));
  std::string pod = fmt::format(
      R"(      volumes:
        - name: work
          persistentVolumeClaim:
            claimName: {claim}
)",
      fmt::arg("claim", quoted(job.volume_claim)));
  auto container = [&](const std::string& name, const std::string& command, int cpus,
                       const std::string& indent) {
    return fmt::format(
        R"({i}- name: {name}
{i}  image: {image}
{i}  workingDir: {workdir}
{i}  command: ["/bin/sh", "-c", {command}]
{i}  resources:
{i}    requests:
{i}      cpu: "{cpus}"
{i}  volumeMounts:
{i}    - name: work
{i}      mountPath: {workdir}
)",
        fmt::arg("i", indent), fmt::arg("name", name), fmt::arg("image", quoted(job.image)),
        fmt::arg("workdir", quoted(job.workdir.string())), fmt::arg("command", quoted(command)),
        fmt::arg("cpus", cpus));
  };
  return fmt::format(
      R"(# planet {command} as a Kubernetes Indexed Job of {tasks} pods, then one merge.
# Apply with: kubectl apply -f THIS_FILE
# Pod K runs the command with --shard K/{tasks} (K from JOB_COMPLETION_INDEX).
# The job "{name}-merge" waits until all {tasks} shares are written to the
# volume {claim_plain} (mounted at {workdir_plain}, where the command's
# paths are), then puts them together into the output.
apiVersion: batch/v1
kind: Job
metadata:
  name: {name}
spec:
  completionMode: Indexed
  completions: {tasks}
  parallelism: {tasks}
  backoffLimit: {tasks}
  template:
    spec:
      restartPolicy: Never
      containers:
{share_container}{pod}---
apiVersion: batch/v1
kind: Job
metadata:
  name: {name}-merge
spec:
  backoffLimit: 2
  template:
    spec:
      restartPolicy: Never
      initContainers:
{wait_container}      containers:
{merge_container}{pod})",
      fmt::arg("command", job.command.front()), fmt::arg("tasks", job.tasks),
      fmt::arg("name", job.name), fmt::arg("claim_plain", job.volume_claim),
      fmt::arg("workdir_plain", job.workdir.string()),
      fmt::arg("share_container", container("share", share_command, job.cpus_per_task, "        ")),
      fmt::arg("wait_container", container("wait-for-shares", wait_command, 1, "        ")),
      fmt::arg("merge_container", container("merge", merge_command, 1, "        ")),
      fmt::arg("pod", pod));
}

}  // namespace planet
