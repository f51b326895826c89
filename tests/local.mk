# tests/local.mk - filled in as the area grows.
