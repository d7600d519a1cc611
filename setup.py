# The Python package ari_social_sim (python/ari_social_sim), installed by catkin_python_setup.
from catkin_pkg.python_setup import generate_distutils_setup
from setuptools import setup

setup(**generate_distutils_setup(packages=["ari_social_sim", "ari_social_sim.learning"],
                                 package_dir={"": "python"}))
