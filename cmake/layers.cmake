# Modules as layers. Each module is a static library built from src/<dir>/ of its folders; its public
# headers (include/pbrfit/<dir>/) are linked one by one into a directory of its own under
# ${PBRFIT_LAYERS_DIR}/<module>/, and that directory is its only include path. A module therefore sees
# the headers of itself and of the modules it links PUBLIC, and nothing else of include/pbrfit.
set(PBRFIT_LAYERS_DIR ${CMAKE_BINARY_DIR}/layers)
set_property(GLOBAL PROPERTY PBRFIT_MODULES "")

# Unity builds of the modules (not of the tests): a module's sources are compiled in batches of at most 12
# files of one folder, which share their names (anonymous namespaces, namespace aliases); files of
# different folders need not. The program builds from scratch in a third of the time (docs/BENCHMARKS.md,
# "First demo"); an edit recompiles its batch. -DPBRFIT_UNITY_BUILD=OFF compiles file by file.
option(PBRFIT_UNITY_BUILD "compile each module's folders in batches of 12 files" ON)

function(pbrfit_unity_groups target sources)
  if(NOT PBRFIT_UNITY_BUILD)
    return()
  endif()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
  set(previous "")
  set(count 0)
  foreach(source IN LISTS sources)
    # A library's implementation file (stb's) stands alone: its settings must reach its header first.
    file(STRINGS ${source} implementation REGEX "#define [A-Z_]+_IMPLEMENTATION")
    if(implementation)
      set_source_files_properties(${source} TARGET_DIRECTORY ${target} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
      continue()
    endif()
    get_filename_component(folder ${source} DIRECTORY)
    file(RELATIVE_PATH folder ${CMAKE_SOURCE_DIR} ${folder})
    if(NOT folder STREQUAL previous)
      set(previous ${folder})
      set(count 0)
    endif()
    math(EXPR batch "${count} / 12")
    math(EXPR count "${count} + 1")
    string(MAKE_C_IDENTIFIER "${folder}_${batch}" group)
    set_source_files_properties(${source} TARGET_DIRECTORY ${target} PROPERTIES UNITY_GROUP ${group})
  endforeach()
endfunction()

function(pbrfit_module name)
  cmake_parse_arguments(M "" "" "DIRS;PUBLIC;PRIVATE" ${ARGN})
  set(root ${PBRFIT_LAYERS_DIR}/${name})
  set(sources)
  set(headers)
  foreach(dir IN LISTS M_DIRS)
    file(GLOB_RECURSE found CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/${dir}/*.cpp)
    list(APPEND sources ${found})
    file(GLOB_RECURSE public CONFIGURE_DEPENDS RELATIVE ${CMAKE_SOURCE_DIR}/include
         ${CMAKE_SOURCE_DIR}/include/pbrfit/${dir}/*.hpp)
    foreach(header IN LISTS public)
      get_filename_component(folder ${root}/${header} DIRECTORY)
      file(MAKE_DIRECTORY ${folder})
      file(CREATE_LINK ${CMAKE_SOURCE_DIR}/include/${header} ${root}/${header} SYMBOLIC)
      list(APPEND headers ${header})
    endforeach()
  endforeach()
  file(MAKE_DIRECTORY ${root})
  if(sources)
    add_library(${name} STATIC ${sources})
    pbrfit_unity_groups(${name} "${sources}")
    pbrfit_kernel_set_sources(${name} "${sources}")
    target_include_directories(${name} PUBLIC ${root})
    target_link_libraries(${name} PUBLIC ${M_PUBLIC} PRIVATE ${M_PRIVATE})
  else()
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE ${root})
    target_link_libraries(${name} INTERFACE ${M_PUBLIC})
  endif()
  set_property(GLOBAL APPEND PROPERTY PBRFIT_MODULES ${name})
  set_property(GLOBAL PROPERTY PBRFIT_HEADERS_${name} ${headers})
endfunction()

# Kernel sets (include/pbrfit/core/kernel_set.hpp): a file named *_isa_<set>.cpp is compiled alone (never
# in a unity batch: it defines PBRFIT_KERNEL_ISA) with its set's instruction-set flags, without
# contraction into FMA, so that arithmetic rounds as in the generic build, and without errno from math
# functions (pbrfit never reads it), so that sqrt loops vectorize.
set(PBRFIT_KERNEL_FLAGS_generic "")
set(PBRFIT_KERNEL_FLAGS_avx2 -mavx2 -mfma)
set(PBRFIT_KERNEL_FLAGS_avx512 -mavx2 -mfma -mavx512f -mavx512bw -mavx512dq -mavx512vl -mprefer-vector-width=512)
function(pbrfit_kernel_set_sources target sources)
  foreach(source IN LISTS sources)
    if(NOT source MATCHES "_isa_([a-z0-9]+)\\.cpp$")
      continue()
    endif()
    set(set_name ${CMAKE_MATCH_1})
    set(options -ffp-contract=off -fno-math-errno)
    # Clang 14's flatten inlines one level only: the inliner's threshold raised for these files inlines
    # Eigen's templates too, so that no weak copy is shared with another set (tests/layers/kernel_set_objects.sh).
    if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
      list(APPEND options -mllvm -inline-threshold=100000)
    endif()
    if(PBRFIT_X86_KERNELS)
      list(APPEND options ${PBRFIT_KERNEL_FLAGS_${set_name}})
      # GCC 12's own AVX-512 intrinsics warn of their undefined-on-purpose operand (GCC bug 105593),
      # as maybe-uninitialized in the GP kernels and as uninitialized in the DFG line kernel.
      if(set_name STREQUAL "avx512" AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
        list(APPEND options -Wno-maybe-uninitialized -Wno-uninitialized)
      endif()
    endif()
    set_source_files_properties(${source} TARGET_DIRECTORY ${target} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON
                                COMPILE_OPTIONS "${options}")
    set_property(GLOBAL APPEND PROPERTY PBRFIT_KERNEL_SET_SOURCES ${source})
  endforeach()
endfunction()

# One translation unit per public header of every module, compiled with that module's flags only: a
# header that needs anything its layer may not see does not compile.
function(pbrfit_header_checks target)
  get_property(modules GLOBAL PROPERTY PBRFIT_MODULES)
  set(all)
  foreach(module IN LISTS modules)
    get_property(headers GLOBAL PROPERTY PBRFIT_HEADERS_${module})
    if(NOT headers)
      continue()
    endif()
    set(units)
    foreach(header IN LISTS headers)
      string(MAKE_C_IDENTIFIER ${header} id)
      set(unit ${CMAKE_CURRENT_BINARY_DIR}/header_checks/${module}/${id}.cpp)
      file(CONFIGURE OUTPUT ${unit} CONTENT "#include \"${header}\"  // alone: it must be self-contained\n")
      list(APPEND units ${unit})
    endforeach()
    add_library(${target}_${module} OBJECT ${units})
    target_link_libraries(${target}_${module} PRIVATE ${module})
    list(APPEND all ${target}_${module})
  endforeach()
  add_custom_target(${target} DEPENDS ${all})
endfunction()
