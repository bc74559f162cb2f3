// metricmap: metric maps from range data. One binary, one subcommand per job.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <thread>

#include <pcl/console/print.h>
#include <CLI/CLI.hpp>

#include "cli_common.h"
#include "commands.h"
#include "metricmap/common/memory_budget.h"
#include "metricmap/common/parse_number.h"
#include "metricmap/version.h"

namespace {

/// This process's rank when mpirun started it (Open MPI, PMIx and MPICH set these before main,
/// before MPI_Init), -1 otherwise.
int launcherRank() {
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"}) {
    const char* v = std::getenv(name);
    if (v != nullptr && *v != '\0') return std::atoi(v);
  }
  return -1;
}

/// A usage error: one line on stderr, exit 2. Under mpirun every rank parses the same command
/// line and finds the same error: rank 0 prints it, once and before mpirun's report of the
/// failed job (the other ranks wait, silent, until mpirun ends them as rank 0 exits).
int usageLine(const std::string& line) {
  const int rank = launcherRank();
  if (rank > 0) {
    std::this_thread::sleep_for(std::chrono::seconds(2));
    return 2;
  }
  std::cerr << line << std::endl;
  if (rank == 0) std::this_thread::sleep_for(std::chrono::milliseconds(200));
  return 2;
}

int usageError(const std::string& what) {
  return usageLine("metricmap: usage: " + what + " (see --help)");
}

}  // namespace

int main(int argc, char** argv) {
  // A closed stdout must not become the first output file's descriptor.
  metricmap::cli::guardStandardStreams();
  // metricmap reports problems itself, one line each; PCL's own chatter would repeat them.
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);

  CLI::App app{"metricmap " METRICMAP_VERSION " - metric maps from range data"};
  app.set_version_flag("--version", METRICMAP_VERSION);
  app.require_subcommand(1);
  std::string max_memory;
  app.add_option("--max-memory", max_memory,
                 "Memory budget checked before large allocations, e.g. 2G, 512M (default: half "
                 "of physical memory)");
  app.parse_complete_callback([&max_memory] {
    if (max_memory.empty()) return;
    try {
      metricmap::setMemoryBudget(metricmap::parseByteSize(max_memory, "--max-memory"));
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError("--max-memory", e.what());
    }
  });
  metricmap::cli::addInfoCommand(app);
  metricmap::cli::addGridCommand(app);
  metricmap::cli::addOctreeCommand(app);
  metricmap::cli::addCompareCommand(app);
  metricmap::cli::addLinesCommand(app);
  metricmap::cli::addDepthToCloudCommand(app);
  metricmap::cli::addHeightMapCommand(app);
  metricmap::cli::addKittiCommand(app);
  metricmap::cli::addOdometryCommand(app);
  metricmap::cli::addMapCommand(app);
  metricmap::cli::addViewCommand(app);
  metricmap::cli::addOccupancyCommand(app);
  metricmap::cli::addEvaluateCommand(app);
  metricmap::cli::addPoseGraphCommand(app);
  metricmap::cli::addSlam2DCommand(app);
  metricmap::cli::addSlam3DCommand(app);
  metricmap::cli::addLocalizeCommand(app);
  metricmap::cli::addDistanceCommand(app);
  if (argc > 1 && argv[1][0] != '-') {
    bool known = false;
    std::string names;  // from the registered commands, in registration order
    for (const CLI::App* sub : app.get_subcommands({})) {
      known = known || sub->check_name(argv[1]);
      names += (names.empty() ? "" : ", ") + sub->get_name();
    }
    if (!known) {
      return usageLine("metricmap: usage: unknown subcommand '" + std::string(argv[1]) + "' (" +
                       names + "; see --help)");
    }
  }
  // Help and version text that cannot be written (a full disk, a closed pipe) is an error too.
  const auto printed = [](int code) {
    std::cout.flush();
    if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout) != 0) {
      std::cerr << "metricmap: error: cannot write to standard output\n";
      return 1;
    }
    return code;
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return printed(app.exit(e));
  } catch (const CLI::CallForAllHelp& e) {
    return printed(app.exit(e));
  } catch (const CLI::CallForVersion& e) {
    return printed(app.exit(e));
  } catch (const CLI::ParseError& e) {
    return usageError(e.what());
  } catch (const metricmap::cli::UsageError& e) {
    return usageError(e.what());
  } catch (const std::bad_alloc&) {
    // Large allocations are checked against the budget with a message naming their option or
    // input; one that slipped through still names what was asked: the command line.
    std::string asked;
    for (int i = 1; i < argc && asked.size() < 200; ++i)
      asked += (i > 1 ? " " : "") + metricmap::quoteForMessage(argv[i]);
    std::cerr << "metricmap: error: out of memory running 'metricmap " << asked
              << "' (an input or option asks for more memory than there is; see --max-memory)\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "metricmap: error: " << e.what() << "\n";
    return 1;
  }
  // A full disk or a closed pipe may only show when standard output is flushed.
  if (std::fflush(stdout) != 0 || std::ferror(stdout) != 0) {
    std::cerr << "metricmap: error: cannot write to standard output\n";
    return 1;
  }
  return 0;
}
