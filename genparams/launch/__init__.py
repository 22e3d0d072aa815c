"""Launch files read and never run: the nodes they start, with their names and parameters."""
