from setuptools import setup

from genparams.setuptools import build_py, develop

PACKAGE = "lidar_filter"

setup(
    name=PACKAGE,
    version="0.1.0",
    packages=[PACKAGE],
    data_files=[
        ("share/ament_index/resource_index/packages", [f"resource/{PACKAGE}"]),
        (f"share/{PACKAGE}", ["package.xml"]),
    ],
    install_requires=["setuptools"],
    zip_safe=True,
    description="Range filter for a lidar scan.",
    license="Apache-2.0",
    entry_points={"console_scripts": [f"filter_node = {PACKAGE}.node:main"]},
    # Generates the modules listed in [tool.genparams] of pyproject.toml.
    cmdclass={"build_py": build_py, "develop": develop},
)
