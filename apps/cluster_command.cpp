// planet cluster slurm|kubernetes: a reference or capture split into
// shares by a cluster's own scheduler, written as a job the user submits.
#include "apps/cli_options.h"
#include "apps/commands.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "lab/gpu/cluster_job.h"

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace planet::apps {

namespace {

struct ClusterArgs {
  int tasks = 0;
  int cpus = 1;
  std::string script, time_limit, partition, program;
  std::string image = "planet:latest", volume_claim = "planet-work", workdir = "/work";
};

enum class Scheduler { kSlurm, kKubernetes };

void run_cluster(const ClusterArgs& args, Scheduler scheduler,
                 const std::vector<std::string>& command) {
  if (args.tasks < 1) throw InputError("cluster: --tasks N (the shares) is required");
  ClusterJob job = plan_cluster_job(command, args.tasks);
  job.cpus_per_task = args.cpus;
  job.time_limit = args.time_limit;
  job.partition = args.partition;
  std::string text;
  if (scheduler == Scheduler::kSlurm) {
    // The program and folder of this run: a cluster's nodes share them.
    job.program = args.program.empty() ? std::filesystem::read_symlink("/proc/self/exe").string()
                                       : args.program;
    job.workdir = std::filesystem::current_path();
    text = slurm_job_script(job);
  } else {
    job.program = args.program.empty() ? "planet" : args.program;  // on the image's PATH
    job.workdir = args.workdir;
    job.image = args.image;
    job.volume_claim = args.volume_claim;
    text = kubernetes_manifest(job);
  }
  if (args.script.empty()) {
    std::fputs(text.c_str(), stdout);
    return;
  }
  std::filesystem::path file(args.script);
  write_file_atomically(file, text);
  if (scheduler == Scheduler::kSlurm) {
    std::filesystem::permissions(file, std::filesystem::perms::owner_exec,
                                 std::filesystem::perm_options::add);
  }
  std::printf("wrote %s: %s\n", file.string().c_str(),
              scheduler == Scheduler::kSlurm
                  ? "submit it with bash (it queues the array and the merge)"
                  : "apply it with kubectl apply -f");
}

void add_common(CLI::App* cmd, const std::shared_ptr<ClusterArgs>& args) {
  // The command to split comes as extras: its own options are its own.
  cmd->allow_extras();
  cmd->add_option("--tasks", args->tasks, "Shares (tasks), N; required")->check(within(1, 65536));
  cmd->add_option("--cpus", args->cpus, "Cores per task (default 1)")->check(within(1, 4096));
  cmd->add_option("--script", args->script, "Write the job here (default: standard output)");
}

}  // namespace

void add_cluster_command(CLI::App& app) {
  CLI::App* cluster = app.add_subcommand(
      "cluster", "Split a reference or capture over a cluster's scheduler (Slurm, Kubernetes)");
  cluster->require_subcommand(1);
  cluster->footer(
      "Each task runs the command with --shard K/N; a merge job puts the shares together "
      "into the command's --out, byte for byte the run made at once. See docs/cluster.md.");

  auto slurm_args = std::make_shared<ClusterArgs>();
  CLI::App* slurm = cluster->add_subcommand(
      "slurm",
      "A script that queues a Slurm job array and its dependent merge job (run it with bash): "
      "planet cluster slurm --tasks N reference|capture ...");
  add_common(slurm, slurm_args);
  slurm->add_option("--time", slurm_args->time_limit, "Time limit per task (Slurm --time)");
  slurm->add_option("--partition", slurm_args->partition, "Slurm partition");
  slurm->add_option("--planet", slurm_args->program,
                    "The planet program on the nodes (default: this one)");
  slurm->callback(
      [slurm, slurm_args] { run_cluster(*slurm_args, Scheduler::kSlurm, slurm->remaining()); });

  auto k8s_args = std::make_shared<ClusterArgs>();
  CLI::App* k8s = cluster->add_subcommand(
      "kubernetes",
      "A Kubernetes Indexed Job manifest and its merge Job (for kubectl apply): "
      "planet cluster kubernetes --tasks N reference|capture ...");
  add_common(k8s, k8s_args);
  k8s->add_option("--image", k8s_args->image, "Container image with planet on its PATH");
  k8s->add_option("--volume-claim", k8s_args->volume_claim,
                  "PersistentVolumeClaim shared by the pods (the command's files)");
  k8s->add_option("--workdir", k8s_args->workdir, "Where the volume is mounted, and the pods run");
  k8s->add_option("--planet", k8s_args->program,
                  "The planet program in the image (default: planet)");
  k8s->callback(
      [k8s, k8s_args] { run_cluster(*k8s_args, Scheduler::kKubernetes, k8s->remaining()); });
}

}  // namespace planet::apps
