"""``genparams import-node``: a schema from a running node, read over its parameter services."""
