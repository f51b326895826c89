# lib/trace/local.mk - filled in as the area grows.
