# lib/image/local.mk - filled in as the area grows.
