# man/local.mk - manual pages.
dist_man_MANS += man/zrcube.1
dist_man_MANS += man/zrcube_mpi.3
