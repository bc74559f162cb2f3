# PCL's io component pulls in VTK; keep the component list short for configure speed.
find_package(PCL 1.12 REQUIRED COMPONENTS common io filters octree sample_consensus kdtree registration)
# What metricmap::core's public headers need: PCL common and filters (no VTK, no PCL io).
set(PCL_CORE_INCLUDE_DIRS ${PCL_COMMON_INCLUDE_DIRS} ${PCL_FILTERS_INCLUDE_DIRS})
list(REMOVE_DUPLICATES PCL_CORE_INCLUDE_DIRS)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(nlohmann_json 3.2 REQUIRED)
find_package(yaml-cpp REQUIRED)
find_package(octomap 1.9 REQUIRED)  # OctoMap .bt/.ot files (linked privately)
if(METRICMAP_BUILD_APPS)
  find_package(CLI11 REQUIRED)
endif()
# Image decoders with error reporting (damaged or hostile depth/RGB images).
find_package(PNG REQUIRED)
find_package(TIFF REQUIRED)
# MPI (OpenMPI on Debian) for the distributed library metricmap_mpi and `--distributed`:
# on by default when found; the core library never links it.
find_package(MPI QUIET COMPONENTS CXX)
option(METRICMAP_WITH_MPI "Build metricmap_mpi and the CLI's --distributed (needs MPI)" ${MPI_CXX_FOUND})
if(METRICMAP_WITH_MPI AND NOT MPI_CXX_FOUND)
  message(FATAL_ERROR "METRICMAP_WITH_MPI is ON but no MPI was found (apt install libopenmpi-dev openmpi-bin)")
endif()
