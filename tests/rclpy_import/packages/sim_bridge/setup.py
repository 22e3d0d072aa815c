from setuptools import setup

setup(name="sim_bridge", version="0.1.0", packages=["sim_bridge"])
