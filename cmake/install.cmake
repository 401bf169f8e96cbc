# `cmake --install BUILD --prefix PREFIX`: the public headers, the static libraries and a CMake
# package, so that another project can find_package(amrstream) and link amrstream::amrstream.
include(CMakePackageConfigHelpers)
include(GNUInstallDirs)

set_target_properties(amrstream_api PROPERTIES EXPORT_NAME amrstream OUTPUT_NAME amrstream)
set_target_properties(amrstream_api_mpi PROPERTIES EXPORT_NAME distributed
                                                   OUTPUT_NAME amrstream_distributed)
# Every static library the two link, which a consumer's link needs too.
set(amrstream_installed amrstream_api amrstream_api_mpi amrstream_core amrstream_bricks
    amrstream_synth amrstream_formats amrstream_flow amrstream_output amrstream_vk amrstream_gpu
    amrstream_render amrstream_image amrstream_annotations amrstream_slice amrstream_mpi
    amrstream_bench)
install(TARGETS ${amrstream_installed} EXPORT amrstreamTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT library
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# The viewer's header goes with the viewer, which the package does not hold.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/amrstream
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT library
        PATTERN viewer.hpp EXCLUDE)
set(package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/amrstream)
install(EXPORT amrstreamTargets NAMESPACE amrstream:: DESTINATION ${package_dir}
        COMPONENT library)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/amrstreamConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/amrstreamConfig.cmake
                              INSTALL_DESTINATION ${package_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/amrstreamConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/amrstreamConfig.cmake
              ${PROJECT_BINARY_DIR}/amrstreamConfigVersion.cmake
        DESTINATION ${package_dir} COMPONENT library)
