# SPDX-License-Identifier: MIT
# The dependency arrows of DESIGN.md, checked on every #include of the tree (a ctest runs
# this with -DSOURCE_DIR=...): apps -> exploration -> {planner, predictor} -> slam, and inside
# slam  core <- rbpf <- map3d <- eval <- segslam,  rbpf <- hybrid;  inside core
# geometry <- grid <- sensor <- io <- config. Fails naming the file, line and the include
# that breaks a rule.
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

set(above_slam "lookahead/(planner|predictor|exploration|pipeline)/")
rule("slam sees no layer above it" slam "${above_slam}")

# The parts of slam, each seeing only the parts it links.
rule("core is the bottom of slam" slam/core "lookahead/slam/(rbpf|octree|rbpf3d|sim3d|segslam|hybrid|eval)/")
rule("rbpf sees core only" slam/rbpf "lookahead/slam/(octree|rbpf3d|sim3d|segslam|hybrid|eval)/")
rule("map3d sees core and rbpf only" slam/map3d "lookahead/slam/(segslam|hybrid|eval)/")
rule("eval sees core and map3d only" slam/eval "lookahead/slam/(segslam|hybrid)/")
rule("hybrid sees core and rbpf only" slam/hybrid "lookahead/slam/(octree|rbpf3d|sim3d|segslam|eval)/")
rule("segslam does not see hybrid" slam/segslam "lookahead/slam/hybrid/")

# Inside core, geometry <- grid <- sensor <- io <- config.
foreach(dir include/lookahead/slam src)
  rule("geometry is the bottom of core" slam/core/${dir}/geometry "lookahead/slam/(grid|sensor|io|config)/")
  rule("grid sees geometry only" slam/core/${dir}/grid "lookahead/slam/(sensor|io|config)/")
  rule("sensor sees geometry and grid only" slam/core/${dir}/sensor "lookahead/slam/(io|config)/")
  rule("io does not see config" slam/core/${dir}/io "lookahead/slam/config/")
endforeach()

# The layers above slam.
rule("planner depends on slam's grid and geometry only" planner
     "lookahead/(predictor|exploration|pipeline)/|lookahead/slam/(rbpf|segslam|hybrid|octree|rbpf3d|sim3d|sensor|eval|io|config)/")
rule("predictor depends on slam's maps only" predictor
     "lookahead/(planner|exploration|pipeline)/|lookahead/slam/(rbpf|segslam|hybrid|octree|rbpf3d|sim3d|eval)/")
rule("exploration sees slam's core and rbpf only" exploration
     "lookahead/pipeline/|lookahead/slam/(segslam|hybrid|octree|rbpf3d|sim3d|eval)/")
rule("the log pipeline sees predictor and slam's core and rbpf only" apps/pipeline
     "lookahead/exploration/|lookahead/slam/(segslam|hybrid|octree|rbpf3d|sim3d|eval)/")

if(violations)
  message(FATAL_ERROR "dependency rules broken:${violations}")
endif()
message(STATUS "dependency rules hold")
