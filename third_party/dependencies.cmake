# CMake glue for the system packages the project uses (Debian 12). No sources are copied into the repo:
# every library comes from its Debian package (installed by ../setup.sh). Included from the top-level
# CMakeLists.txt so that the imported targets are visible everywhere.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
