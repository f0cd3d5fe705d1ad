#pragma once
// A planet command split over a cluster by the cluster's own scheduler:
// N tasks, task K running the command with `--shard K/N`, then one merge
// that puts the shares together into the command's --out. Written as a
// Slurm job-array script (sbatch) or a Kubernetes Indexed Job manifest.
#include <filesystem>
#include <string>
#include <vector>

namespace planet {

struct ClusterJob {
  std::string name;                  // job name, from the command and its scene or flight
  std::string program;               // the planet program as the tasks run it
  std::filesystem::path workdir;     // where the command's relative paths are
  std::vector<std::string> command;  // a share's arguments, less --shard
  std::vector<std::string> merge;    // the merge's arguments
  std::string share_done;            // a shell glob: one match per finished share
  int tasks = 1;
  int cpus_per_task = 1;
  std::string time_limit;    // Slurm's --time, or empty
  std::string partition;     // Slurm's --partition, or empty
  std::string image;         // Kubernetes: the container image holding planet
  std::string volume_claim;  // Kubernetes: the shared volume's claim
};

// The job for `args` (a planet command line without the program:
// "reference --scene earth_noon --spp 4096 --out refs/noon.exr", or
// "capture --flight F --out DIR"), checked as the command itself would
// check it, before any task is queued: InputError naming what is wrong.
// `tasks` and the fields past it are left for the caller to fill.
ClusterJob plan_cluster_job(const std::vector<std::string>& args, int tasks);

// Run it with bash where sbatch works: it queues an array of `tasks` tasks,
// then the merge, held until every task has ended well (afterok). The
// tasks queue nothing: compute nodes need no sbatch.
std::string slurm_job_script(const ClusterJob& job);

// `kubectl apply -f` it: an Indexed Job of `tasks` completions (pod K reads
// K from JOB_COMPLETION_INDEX) and a merge Job that waits for every share.
std::string kubernetes_manifest(const ClusterJob& job);

}  // namespace planet
