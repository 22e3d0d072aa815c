from setuptools import find_packages, setup

from genparams.setuptools import build_py, develop

PACKAGE = "gripper_driver"

setup(
    name=PACKAGE,
    version="0.1.0",
    package_dir={"": "src"},
    packages=find_packages("src"),
    data_files=[
        ("share/ament_index/resource_index/packages", [f"resource/{PACKAGE}"]),
        (f"share/{PACKAGE}", ["package.xml"]),
    ],
    install_requires=["setuptools"],
    zip_safe=True,
    description="Gripper driver.",
    license="Apache-2.0",
    entry_points={"console_scripts": [f"gripper_node = {PACKAGE}.node:main"]},
    # Generates the modules listed in [tool.genparams] of pyproject.toml.
    cmdclass={"build_py": build_py, "develop": develop},
)
