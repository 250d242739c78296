// The ranks of an MPI launch read from the launcher's environment (see launcher_ranks.hpp).
#include "run/launcher_ranks.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>

#include "core/errors.hpp"

namespace arksph {

namespace {

const char* env(const char* name) {
  const char* v = std::getenv(name);
  return v && *v ? v : nullptr;
}

int env_int(const char* name, const char* value) {
  char* end = nullptr;
  const long v = std::strtol(value, &end, 10);
  if (*end || v < 0 || v > 1000000) throw InputError(std::string("batch: ") + name + "=" + value + " is not a rank count or rank");
  return static_cast<int>(v);
}

}  // namespace

std::string host_name() {
  char h[256] = {};
  gethostname(h, sizeof h - 1);
  return h;
}

LauncherRanks launcher_ranks_from_environment() {
  LauncherRanks lr;
  const char* size = env("OMPI_COMM_WORLD_SIZE");
  const char* rank = env("OMPI_COMM_WORLD_RANK");
  const char* local = env("OMPI_COMM_WORLD_LOCAL_SIZE");
  const char* size_name = "OMPI_COMM_WORLD_SIZE";
  if (!size || !rank) {
    size = env("PMI_SIZE");
    rank = env("PMI_RANK");
    local = env("MPI_LOCALNRANKS");
    size_name = "PMI_SIZE";
  }
  if (!size || !rank) return lr;
  lr.size = env_int(size_name, size);
  lr.rank = env_int("rank", rank);
  lr.local_size = local ? std::max(1, env_int("local size", local)) : 1;
  if (lr.size < 1 || lr.rank >= lr.size)
    throw InputError(std::string("batch: launcher rank ") + rank + " of " + size + " is not a rank");
  for (const char* id : {"PMIX_NAMESPACE", "OMPI_MCA_ess_base_jobid", "PMI_KVSNAME"})
    if (const char* v = env(id)) {
      lr.launch = std::string(id) + "=" + v;
      return lr;
    }
  lr.launch = host_name() + ":" + std::to_string(getppid());
  return lr;
}

void forget_launcher_ranks() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_LOCAL_SIZE", "PMI_SIZE",
                           "PMI_RANK", "MPI_LOCALNRANKS"})
    unsetenv(name);
}

}  // namespace arksph
