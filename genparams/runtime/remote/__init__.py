"""A typed client of another node's parameters: get, set and watch over its parameter services."""
