# Run by `cmake --install` of the plugin build: lists the installed UnstructuredVolume.plugins.xml in
# ParaView's configuration file, so that ParaView knows the plugin by name (Tools > Manage Plugins,
# `LoadDistributedPlugin("UnstructuredVolume")`) and a user can tick it to load at start-up.
#
# ParaView reads one configuration file, paraview.conf, one plugin-list path per line:
#  - Debian's ParaView 5.13 and newer: <libdir>/paraview-X.Y/paraview.conf, beside the plugin folder;
#  - ParaView's own rule (Kitware's binaries, Debian's 5.11): beside the executable, <prefix>/bin.
# Where the file does not exist yet it is made, listing ParaView's own plugin list first: once the
# file exists, ParaView reads only what it names.
#
# In: UV_PARAVIEW_PREFIX, UV_PARAVIEW_PLUGIN_DIR (ParaView's plugin folder), UV_PLUGIN_LIST (ours).
get_filename_component(uv_distribution_conf "${UV_PARAVIEW_PLUGIN_DIR}/../paraview.conf" ABSOLUTE)
if (EXISTS "${uv_distribution_conf}")
  set(uv_conf "${uv_distribution_conf}")
else ()
  set(uv_conf "${UV_PARAVIEW_PREFIX}/bin/paraview.conf")
endif ()
set(uv_conf_written "$ENV{DESTDIR}${uv_conf}")

set(uv_lines "")
if (EXISTS "${uv_conf_written}")
  file(STRINGS "${uv_conf_written}" uv_lines)
elseif (EXISTS "${UV_PARAVIEW_PLUGIN_DIR}/paraview.plugins.xml")
  list(APPEND uv_lines "${UV_PARAVIEW_PLUGIN_DIR}/paraview.plugins.xml")
endif ()
if ("${UV_PLUGIN_LIST}" IN_LIST uv_lines)
  message(STATUS "Up-to-date: ${uv_conf_written} lists ${UV_PLUGIN_LIST}")
  return ()
endif ()
list(APPEND uv_lines "${UV_PLUGIN_LIST}")
list(JOIN uv_lines "\n" uv_text)
file(WRITE "${uv_conf_written}" "${uv_text}\n")
message(STATUS "Registered: ${uv_conf_written} lists ${UV_PLUGIN_LIST}")
