# man/local.mk - manual pages.
dist_man_MANS += man/zrcube.1
dist_man_MANS += man/zrcube_mpi.3
# One page per family of library functions; libzrcube(3) is the index.
dist_man_MANS += man/zr_context_new.3 man/zr_context_set_progress.3 \
	man/zr_status_str.3 man/zr_scene_parse_file.3 man/zr_render_image.3 \
	man/zr_radiosity_solve.3 man/zr_gi_cache_new.3 man/zr_image_write.3 \
	man/zr_scene_preview.3
