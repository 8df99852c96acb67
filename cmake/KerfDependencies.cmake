# Every dependency comes from Debian's packages; nothing is downloaded.
find_package(Threads REQUIRED)
find_package(tomlplusplus REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(GTest REQUIRED)
find_package(benchmark REQUIRED)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(PkgConfig REQUIRED)
pkg_check_modules(POLYCLIPPING REQUIRED IMPORTED_TARGET polyclipping)
if(KERF_BUILD_UI)
  find_package(Qt5 5.15 REQUIRED COMPONENTS Core Gui Widgets Test LinguistTools)
endif()
# VTK for graphics/ (no Qt) and ui/viewport (GUISupportQt). Debian's VTK config names MPI::MPI_C in
# the link interface of its MPI module even when no MPI module is asked for: without an MPI
# installation a stand-in target lets the configuration load; Kerf links no MPI module.
find_package(MPI QUIET COMPONENTS C)
if(NOT TARGET MPI::MPI_C)
  add_library(MPI::MPI_C INTERFACE IMPORTED)
endif()
set(KERF_VTK_COMPONENTS CommonCore CommonDataModel CommonExecutionModel CommonMath CommonTransforms
  RenderingCore RenderingOpenGL2 RenderingAnnotation RenderingFreeType InteractionStyle IOImage)
if(KERF_BUILD_UI)
  list(APPEND KERF_VTK_COMPONENTS GUISupportQt)
endif()
find_package(VTK 9.1 REQUIRED COMPONENTS ${KERF_VTK_COMPONENTS})
