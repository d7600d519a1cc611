# The layers of the project's libraries, lowest first. A library may link libraries of its own
# layer or of a layer below, never one above; every library the build defines must be in exactly
# one layer. docs/ARCHITECTURE.md ("Layers") shows the same list, and test/scripts/test_layers.py
# compares the two. Finer rules inside a layer (navigation free of the simulator) stay with
# ari_forbid_link.
set(ari_layers foundation simulation robot_and_senses engine products ros)
set(ari_layer_foundation ari_core ari_model)
set(ari_layer_simulation ari_world ari_dialogue ari_navigation)
set(ari_layer_robot_and_senses
  ari_perception ari_physics ari_rendering ari_mapping ari_audio ari_world_speech)
set(ari_layer_engine ari_scenario ari_engine)
set(ari_layer_products ari_batch ari_dataset ari_learning ari_parameters_page)
set(ari_layer_ros
  ari_node_support ari_world_conversions ari_perception_conversions ari_dialogue_conversions
  ari_navigation_conversions ari_scenario_conversions ari_episode_bag)
# The folders of src/ that build programs rather than a library.
set(ari_program_folders nodes tools python)

# ari_layer_of(<library> <out-var>): the index of <library>'s layer in ari_layers, or -1.
function(ari_layer_of library out_var)
  set(index 0)
  foreach(layer IN LISTS ari_layers)
    if(library IN_LIST ari_layer_${layer})
      set(${out_var} ${index} PARENT_SCOPE)
      return()
    endif()
    math(EXPR index "${index} + 1")
  endforeach()
  set(${out_var} -1 PARENT_SCOPE)
endfunction()

# ari_check_folders(<targets>): stops the configure step unless each folder of src/ is a library's
# (src/X/ holds the sources of ari_X and of nothing else) or a folder of programs, and each
# include/ari_social_sim/X/ is the public headers' folder of such a library: one library, one folder.
function(ari_check_folders targets)
  foreach(target IN LISTS targets)
    get_target_property(sources ${target} SOURCES)
    foreach(source IN LISTS sources)
      if(NOT source MATCHES "^src/([^/]+)/")
        continue()
      endif()
      set(folder ${CMAKE_MATCH_1})
      if(folder IN_LIST ari_program_folders)
        get_target_property(type ${target} TYPE)
        if(type MATCHES "LIBRARY$" AND target MATCHES "^ari_")
          message(FATAL_ERROR "layers: library ${target} compiles ${source}, in a folder of "
            "programs; its sources belong in its own folder (docs/ARCHITECTURE.md, Layers)")
        endif()
      elseif(NOT target STREQUAL "ari_${folder}")
        message(FATAL_ERROR "layers: ${target} compiles ${source}, which is library "
          "ari_${folder}'s folder: a library's sources lie in src/<its name without ari_>/, and "
          "no other target compiles them (docs/ARCHITECTURE.md, Layers)")
      endif()
    endforeach()
  endforeach()
  file(GLOB folders LIST_DIRECTORIES true RELATIVE ${PROJECT_SOURCE_DIR}/src
    ${PROJECT_SOURCE_DIR}/src/*)
  file(GLOB headers LIST_DIRECTORIES true RELATIVE ${PROJECT_SOURCE_DIR}/include/ari_social_sim
    ${PROJECT_SOURCE_DIR}/include/ari_social_sim/*)
  foreach(folder IN LISTS folders headers)
    if(IS_DIRECTORY ${PROJECT_SOURCE_DIR}/src/${folder} AND folder IN_LIST ari_program_folders)
      continue()
    endif()
    if(NOT TARGET ari_${folder})
      message(FATAL_ERROR "layers: src/${folder}/ or include/ari_social_sim/${folder}/ builds no "
        "library ari_${folder}: each folder is one library (docs/ARCHITECTURE.md, Layers)")
    endif()
  endforeach()
endfunction()

# ari_check_layers(): stops the configure step when a library of the project (an ari_* library
# target) is in no layer, links (directly) a library of a layer above its own, or compiles sources
# outside its folder, or a folder builds no library (ari_check_folders).
function(ari_check_layers)
  get_directory_property(targets BUILDSYSTEM_TARGETS)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(NOT target MATCHES "^ari_" OR NOT type MATCHES "LIBRARY$")
      continue()
    endif()
    ari_layer_of(${target} own)
    if(own EQUAL -1)
      message(FATAL_ERROR "layers: library ${target} is in no layer; add it to cmake/layers.cmake "
        "and to docs/ARCHITECTURE.md (Layers)")
    endif()
    list(GET ari_layers ${own} own_name)
    get_target_property(links ${target} LINK_LIBRARIES)
    foreach(link IN LISTS links)
      ari_layer_of("${link}" theirs)
      if(theirs GREATER own)
        list(GET ari_layers ${theirs} their_name)
        message(FATAL_ERROR "layers: ${target} (layer ${own_name}) links ${link}, which is in "
          "the layer above it, ${their_name}: a library may link only its own layer and those "
          "below (cmake/layers.cmake)")
      endif()
    endforeach()
  endforeach()
  ari_check_folders("${targets}")
  message(STATUS "layers: every library links only its own layer and those below")
endfunction()
