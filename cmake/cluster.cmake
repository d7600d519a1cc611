# Batch plans on SLURM (scripts/slurm_batch.py, docs/cluster.md): their test starts a SLURM cluster
# of one host from Debian's packages and runs the tools' shards and merges on it.
if(CATKIN_ENABLE_TESTING)
  catkin_run_tests_target(pytest cluster pytest-cluster.xml
    COMMAND "${CMAKE_COMMAND} -E env ARI_DEVEL_DIR=${CATKIN_DEVEL_PREFIX} /usr/bin/python3 -m pytest -q -p no:cacheprovider --junitxml=${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/pytest-cluster.xml ${PROJECT_SOURCE_DIR}/test/cluster"
    DEPENDENCIES run_episodes export_dataset)
endif()
