"""The compiler front: load a schema file, check it, build the frozen model.

Stages run one way: ``loader`` -> ``schema_check`` -> ``builder`` (with
``rule_builder`` and ``references``) -> ``model``. ``specs`` compiles the model
through the runtime's own validators, so every output describes a constraint
with the text of the object that enforces it.
"""
