# One library target per layer (README, Architecture): anchorbench_<NAME> with the alias
# anchorbench::<NAME>, its headers in <NAME>/include/anchorbench/<NAME>/, C++20 for its consumers
# too, and its tests/ folder when present (the benchmarks sit above every layer, in bench/).
#   anchorbench_add_library(NAME SOURCES file... DEPENDS target... [PRIVATE_DEPENDS target...])
function(anchorbench_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS;PRIVATE_DEPENDS" ${ARGN})
  set(target anchorbench_${name})
  add_library(${target} ${ARG_SOURCES})
  add_library(anchorbench::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:include>)
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_link_libraries(${target} PUBLIC ${ARG_DEPENDS} PRIVATE ${ARG_PRIVATE_DEPENDS})
  set_property(GLOBAL APPEND PROPERTY ANCHORBENCH_LIBRARIES ${target})
  install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  if(ANCHORBENCH_BUILD_TESTS AND EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/tests/CMakeLists.txt)
    add_subdirectory(tests)
  endif()
endfunction()

# A GoogleTest executable <NAME>_tests whose tests CTest discovers.
#   anchorbench_add_tests(NAME SOURCES file... DEPENDS target...)
function(anchorbench_add_tests name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
  add_executable(${name}_tests ${ARG_SOURCES})
  target_link_libraries(${name}_tests PRIVATE ${ARG_DEPENDS} GTest::gtest_main)
  gtest_discover_tests(${name}_tests DISCOVERY_TIMEOUT 60)
endfunction()

# Fails the configuration if an arrow points the wrong way: each layer of LAYERS (bottom to top)
# may link only layers listed before it, plus the third-party targets ALLOWED for it (pairs
# layer "dep,dep"); a third-party target allowed to one layer reaches the layers above it only
# through that layer.
#   anchorbench_check_layers(LAYERS a b c ALLOWED a "Eigen3::Eigen,NLopt::nlopt_cxx" c "yaml-cpp")
function(anchorbench_check_layers)
  cmake_parse_arguments(ARG "" "" "LAYERS;ALLOWED" ${ARGN})
  set(below "")
  while(ARG_ALLOWED)
    list(POP_FRONT ARG_ALLOWED layer deps)
    string(REPLACE "," ";" allowed_${layer} "${deps}")
  endwhile()
  foreach(layer IN LISTS ARG_LAYERS)
    get_target_property(links anchorbench_${layer} LINK_LIBRARIES)
    if(NOT links)
      set(links "")
    endif()
    foreach(link IN LISTS links)
      string(REGEX REPLACE "^anchorbench::" "" name "${link}")
      if(NOT name IN_LIST below AND NOT link IN_LIST allowed_${layer})
        message(FATAL_ERROR "layer '${layer}' links '${link}': a layer may link only layers below it "
                            "(${below}) and its own third-party parts (${allowed_${layer}})")
      endif()
    endforeach()
    list(APPEND below ${layer})
  endforeach()
endfunction()
