"""The live ROS graph, read once for every tool: nodes, their parameters, schemas and events."""
