# SPDX-License-Identifier: MIT
# The dependency arrows of DESIGN.md, checked on every #include of the tree (a ctest runs
# this with -DSOURCE_DIR=...): apps -> exploration -> {planner, predictor} -> slam. Fails
# naming the file, line and the include that breaks a rule.
#   rule(NAME FOLDER REGEX): no file under FOLDER may include a header matching REGEX.
set(violations "")
function(rule name folder regex)
  file(GLOB_RECURSE files ${SOURCE_DIR}/${folder}/*.hpp ${SOURCE_DIR}/${folder}/*.cpp)
  foreach(f ${files})
    file(STRINGS ${f} lines REGEX "^#include \"lookahead/")
    foreach(line ${lines})
      if(line MATCHES "${regex}")
        file(RELATIVE_PATH rel ${SOURCE_DIR} ${f})
        set(violations "${violations}\n  ${rel}: ${line}  (${name})")
      endif()
    endforeach()
  endforeach()
  set(violations "${violations}" PARENT_SCOPE)
endfunction()

rule("slam sees no layer above it" slam "lookahead/(planner|predictor|exploration)/")
rule("planner depends on slam's grid and geometry only" planner
     "lookahead/(predictor|exploration)/|lookahead/slam/(rbpf|segslam|hybrid|octree|rbpf3d|sim3d|sensor|eval|io|config)/")
rule("predictor depends on slam's maps only" predictor
     "lookahead/(planner|exploration)/|lookahead/slam/(segslam|hybrid|octree|rbpf3d|sim3d)/")
set(above_geometry "lookahead/slam/(grid|sensor|io|config|eval|rbpf|segslam|hybrid|octree|rbpf3d|sim3d)/")
rule("geometry is the bottom of slam" slam/include/lookahead/slam/geometry "${above_geometry}")
rule("geometry is the bottom of slam" slam/src/geometry "${above_geometry}")

if(violations)
  message(FATAL_ERROR "dependency rules broken:${violations}")
endif()
message(STATUS "dependency rules hold")
