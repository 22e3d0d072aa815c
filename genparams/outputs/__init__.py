"""Everything rendered from a model: the Python module, docs pages, the default
params file and the JSON Schema of params files.
"""
