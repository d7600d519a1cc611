# scripts/: the set-up, data and check scripts. Their own tests (pytest) run with the others; the
# checks themselves (dependencies, documents, paths, the repository alone) run in scripts/test.sh.
if(CATKIN_ENABLE_TESTING)
  catkin_run_tests_target(pytest scripts pytest-scripts.xml
    COMMAND "/usr/bin/python3 -m pytest -q -p no:cacheprovider --junitxml=${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/pytest-scripts.xml ${PROJECT_SOURCE_DIR}/test/scripts")
endif()
