# All third-party packages come from Debian; see scripts/install-deps.sh.
find_package(GDAL 3.6 CONFIG REQUIRED)
find_package(PROJ 9 CONFIG REQUIRED)

# GeographicLib ships only a Find module, off the default path, without a target.
list(APPEND CMAKE_MODULE_PATH /usr/share/cmake/geographiclib)
find_package(GeographicLib REQUIRED)
if(NOT TARGET GeographicLib::GeographicLib)
  add_library(GeographicLib::GeographicLib INTERFACE IMPORTED)
  target_include_directories(GeographicLib::GeographicLib INTERFACE ${GeographicLib_INCLUDE_DIRS})
  target_link_libraries(GeographicLib::GeographicLib INTERFACE ${GeographicLib_LIBRARIES})
endif()

# NO_MODULE: CGAL puts its own FindEigen3 on the module path, which gives no target.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(OpenCV 4.6 REQUIRED COMPONENTS core imgproc imgcodecs calib3d features2d)
set(CGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE TRUE)
find_package(CGAL 5.5 REQUIRED)
find_package(GTest REQUIRED)
if(ROOFSWEEP_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
# The CMake package says 2.4.1 although Debian ships 2.4.3.
find_package(citygml 2.4 REQUIRED)
find_package(TBB REQUIRED)
find_package(nlohmann_json 3.11 REQUIRED)
find_package(LibXml2 REQUIRED)

add_library(roofsweep_opencv INTERFACE)
target_include_directories(roofsweep_opencv SYSTEM INTERFACE ${OpenCV_INCLUDE_DIRS})
target_link_libraries(roofsweep_opencv INTERFACE ${OpenCV_LIBS})
