#!/bin/bash -eu
# ClusterFuzzLite / OSS-Fuzz entry point: the image provides $CC $CXX $CFLAGS $CXXFLAGS
# $LIB_FUZZING_ENGINE $OUT $WORK; fuzz/oss_fuzz_build.sh does the rest.
"$SRC/tetcut/fuzz/oss_fuzz_build.sh"
