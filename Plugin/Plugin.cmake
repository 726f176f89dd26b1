# The ParaView plugin: the UnstructuredVolume module plus its server-manager XML.
# Included from the staged plugin folder (see the root CMakeLists.txt).
# The module UnstructuredVolume::vtkUnstructuredVolumeParaView (Plugin/ParaView) holds the ParaView
# representations over the mappers; it exists only in this build.

# The Representation-menu entries come from the table in Plugin/Representations.cmake: each becomes
# an entry on unstructured, structured and image data whose settings the Properties panel shows while
# it is selected.
set(uv_representations_xml "${UV_SOURCE_DIR}/Plugin/UnstructuredVolumeRepresentations.xml")
set(uv_representations_table "${UV_SOURCE_DIR}/Plugin/Representations.cmake")
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
  "${uv_representations_xml}" "${uv_representations_table}")

# One row of the table (the fields are described there).
function (uv_representation_entry)
  cmake_parse_arguments(PARSE_ARGV 0 uv_row "" "PROXY;MENU;GROUP" "PROPERTIES;UNSHARED")
  set(uv_where "${uv_representations_table}, entry ${uv_row_PROXY}")
  if (NOT uv_row_PROXY OR NOT uv_row_MENU OR NOT uv_row_GROUP OR NOT uv_row_PROPERTIES OR uv_row_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "${uv_where}: PROXY, MENU, GROUP and PROPERTIES are required "
      "(not understood: ${uv_row_UNPARSED_ARGUMENTS})")
  endif ()
  if (uv_row_PROXY IN_LIST uv_entries)
    message(FATAL_ERROR "${uv_where}: listed twice")
  endif ()
  set(uv_unique_properties "${uv_row_PROPERTIES}")
  list(REMOVE_DUPLICATES uv_unique_properties)
  if (NOT uv_unique_properties STREQUAL uv_row_PROPERTIES)
    message(FATAL_ERROR "${uv_where}: a property is listed twice in PROPERTIES")
  endif ()
  list(LENGTH uv_row_UNSHARED uv_count)
  math(EXPR uv_odd "${uv_count} % 2")
  if (uv_odd)
    message(FATAL_ERROR "${uv_where}: UNSHARED takes pairs (property, its name in the panel)")
  endif ()
  set(uv_panel_names "${uv_row_PROPERTIES}")
  while (uv_row_UNSHARED)
    list(POP_FRONT uv_row_UNSHARED uv_property uv_panel_name)
    list(FIND uv_row_PROPERTIES "${uv_property}" uv_at)
    if (uv_at EQUAL -1)
      message(FATAL_ERROR "${uv_where}: UNSHARED names ${uv_property}, which is not in its PROPERTIES")
    endif ()
    list(REMOVE_AT uv_panel_names ${uv_at})
    list(INSERT uv_panel_names ${uv_at} "${uv_panel_name}")
  endwhile ()
  list(APPEND uv_entries "${uv_row_PROXY}")
  set(uv_entries "${uv_entries}" PARENT_SCOPE)
  set(uv_entry_${uv_row_PROXY}_menu "${uv_row_MENU}" PARENT_SCOPE)
  set(uv_entry_${uv_row_PROXY}_group "${uv_row_GROUP}" PARENT_SCOPE)
  set(uv_entry_${uv_row_PROXY}_properties "${uv_row_PROPERTIES}" PARENT_SCOPE)
  set(uv_entry_${uv_row_PROXY}_panel_names "${uv_panel_names}" PARENT_SCOPE)
endfunction ()

set(uv_entries "")
include("${uv_representations_table}")

# The table against the XML, by the names the XML declares: every RepresentationProxy is an entry,
# an entry's PROPERTIES are exactly its proxy's properties (Input aside), and entries sharing a panel
# name define that property identically (whitespace aside), since the panel shows only one of them.
file(READ "${uv_representations_xml}" uv_xml)
set(uv_mismatches "")
set(uv_xml_proxies "")
while (TRUE)
  string(FIND "${uv_xml}" "<RepresentationProxy" uv_begin)
  if (uv_begin EQUAL -1)
    break ()
  endif ()
  string(SUBSTRING "${uv_xml}" ${uv_begin} -1 uv_xml)
  string(FIND "${uv_xml}" "</RepresentationProxy>" uv_end)
  string(SUBSTRING "${uv_xml}" 0 ${uv_end} uv_block)
  string(SUBSTRING "${uv_xml}" ${uv_end} -1 uv_xml)
  string(REGEX MATCH "^<RepresentationProxy[^>]*[ \t\r\n]name=\"([^\"]+)\"" uv_tag "${uv_block}")
  set(uv_proxy "${CMAKE_MATCH_1}")
  list(APPEND uv_xml_proxies "${uv_proxy}")
  if (NOT uv_proxy IN_LIST uv_entries)
    list(APPEND uv_mismatches "proxy ${uv_proxy} is in the XML but not in the table")
    continue ()
  endif ()
  string(REGEX MATCHALL "<[A-Za-z]+Property[^>]*[ \t\r\n]name=\"[A-Za-z0-9_]+\"" uv_tags "${uv_block}")
  set(uv_xml_properties "")
  foreach (uv_tag IN LISTS uv_tags)
    string(REGEX MATCH "^<([A-Za-z]+)Property.*[ \t\r\n]name=\"([A-Za-z0-9_]+)\"$" _ "${uv_tag}")
    set(uv_type "${CMAKE_MATCH_1}")
    set(uv_property "${CMAKE_MATCH_2}")
    if (uv_type STREQUAL "Input")
      continue ()
    endif ()
    list(APPEND uv_xml_properties "${uv_property}")
    # Its whole element, up to the closing tag (or the end of the tag if it closes itself).
    string(FIND "${uv_block}" "${uv_tag}" uv_at)
    string(SUBSTRING "${uv_block}" ${uv_at} -1 uv_definition)
    string(FIND "${uv_definition}" ">" uv_close)
    math(EXPR uv_before_close "${uv_close} - 1")
    string(SUBSTRING "${uv_definition}" ${uv_before_close} 1 uv_slash)
    if (NOT uv_slash STREQUAL "/")
      string(FIND "${uv_definition}" "</${uv_type}Property>" uv_close)
    endif ()
    string(SUBSTRING "${uv_definition}" 0 ${uv_close} uv_definition)
    string(REGEX REPLACE "[ \t\r\n]+" " " uv_definition "${uv_definition}")
    set(uv_definition_${uv_proxy}_${uv_property} "${uv_definition}")
  endforeach ()
  foreach (uv_property IN LISTS uv_entry_${uv_proxy}_properties)
    if (NOT uv_property IN_LIST uv_xml_properties)
      list(APPEND uv_mismatches "${uv_proxy}: property ${uv_property} is in the table but not in the proxy's XML")
    endif ()
  endforeach ()
  foreach (uv_property IN LISTS uv_xml_properties)
    if (NOT uv_property IN_LIST uv_entry_${uv_proxy}_properties)
      list(APPEND uv_mismatches "${uv_proxy}: property ${uv_property} is in the proxy's XML but not in the table")
    endif ()
  endforeach ()
endwhile ()
foreach (uv_entry IN LISTS uv_entries)
  if (NOT uv_entry IN_LIST uv_xml_proxies)
    list(APPEND uv_mismatches "proxy ${uv_entry} is in the table but not in the XML")
  endif ()
endforeach ()

# Each panel name's owner (the first entry listing it, whose property the panel shows) and sharers.
set(uv_panel_names "")
foreach (uv_entry IN LISTS uv_entries)
  foreach (uv_property uv_panel_name IN ZIP_LISTS uv_entry_${uv_entry}_properties uv_entry_${uv_entry}_panel_names)
    if (NOT uv_panel_name IN_LIST uv_panel_names)
      list(APPEND uv_panel_names "${uv_panel_name}")
      set(uv_owner_${uv_panel_name} "${uv_entry}")
      set(uv_owned_definition_${uv_panel_name} "uv_definition_${uv_entry}_${uv_property}")
      set(uv_sharers_${uv_panel_name} "")
    elseif (DEFINED uv_definition_${uv_entry}_${uv_property} AND DEFINED ${uv_owned_definition_${uv_panel_name}}
            AND NOT uv_definition_${uv_entry}_${uv_property} STREQUAL ${uv_owned_definition_${uv_panel_name}})
      list(APPEND uv_mismatches "${uv_entry}: property ${uv_property} shares the panel name ${uv_panel_name} with "
        "${uv_owner_${uv_panel_name}} but is defined differently there (define it identically, or list it under UNSHARED)")
    endif ()
    list(APPEND uv_sharers_${uv_panel_name} "${uv_entry}")
  endforeach ()
endforeach ()
if (uv_mismatches)
  list(JOIN uv_mismatches "\n  " uv_mismatches)
  message(FATAL_ERROR "${uv_representations_table} and ${uv_representations_xml} disagree:\n  ${uv_mismatches}")
endif ()

# The panel-visibility hint of a section shown while one of `entries` is selected.
function (uv_visible_while out_var entries)
  set(uv_hint "")
  set(uv_indent "              ")
  list(LENGTH entries uv_count)
  if (uv_count GREATER 1)
    set(uv_hint "${uv_indent}<PropertyWidgetDecorator type=\"CompositeDecorator\">\n${uv_indent}  <Expression type=\"or\">\n")
    set(uv_indent "${uv_indent}    ")
  endif ()
  foreach (uv_entry IN LISTS entries)
    string(APPEND uv_hint "${uv_indent}<PropertyWidgetDecorator type=\"GenericDecorator\" mode=\"visibility\" "
      "property=\"Representation\"\n${uv_indent}                         value=\"${uv_entry_${uv_entry}_menu}\" />\n")
  endforeach ()
  if (uv_count GREATER 1)
    string(APPEND uv_hint "                </Expression>\n              </PropertyWidgetDecorator>\n")
  endif ()
  set(${out_var} "${uv_hint}" PARENT_SCOPE)
endfunction ()

# Each entry's subproxy: it exposes the properties it owns, in one panel section per set of entries
# sharing them (the shared sections first, so every entry's panel has the same order), and shares
# the property objects of those another entry owns (ShareProperties from that entry's subproxy, all
# its other properties excepted). Shared objects, not linked copies: a link does not carry a list
# cleared to no values, so a cleared isovalue list would stay drawn in the other entries.
# SELECT_MAPPER_EXCEPTION is filled in per data representation.
foreach (uv_entry IN LISTS uv_entries)
  set(uv_owners "")
  set(uv_sections "")
  foreach (uv_property uv_panel_name IN ZIP_LISTS uv_entry_${uv_entry}_properties uv_entry_${uv_entry}_panel_names)
    if (NOT uv_owner_${uv_panel_name} STREQUAL uv_entry)
      set(uv_owner "${uv_owner_${uv_panel_name}}")
      if (NOT uv_owner IN_LIST uv_owners)
        list(APPEND uv_owners "${uv_owner}")
        set(uv_taken_${uv_owner} "")
      endif ()
      list(APPEND uv_taken_${uv_owner} "${uv_property}")
      continue ()
    endif ()
    string(REPLACE ";" "," uv_section "${uv_sharers_${uv_panel_name}}")
    if (NOT uv_section IN_LIST uv_sections)
      list(APPEND uv_sections "${uv_section}")
      set(uv_section_${uv_section} "")
    endif ()
    set(uv_exposed_name "")
    if (NOT uv_panel_name STREQUAL uv_property)
      set(uv_exposed_name " exposed_name=\"${uv_panel_name}\"")
    endif ()
    string(APPEND uv_section_${uv_section} "            <Property name=\"${uv_property}\"${uv_exposed_name} />\n")
  endforeach ()
  if (uv_entry IN_LIST uv_sections)
    list(REMOVE_ITEM uv_sections "${uv_entry}")
    list(APPEND uv_sections "${uv_entry}")
  endif ()
  set(uv_exposed "")
  foreach (uv_section IN LISTS uv_sections)
    string(REPLACE "," ";" uv_sharers "${uv_section}")
    set(uv_label "${UV_SHARED_PANEL_GROUP}")
    if (uv_section STREQUAL uv_entry)
      set(uv_label "${uv_entry_${uv_entry}_group}")
    endif ()
    uv_visible_while(uv_hint "${uv_sharers}")
    string(APPEND uv_exposed "          <PropertyGroup label=\"${uv_label}\">\n${uv_section_${uv_section}}"
      "            <Hints>\n${uv_hint}            </Hints>\n          </PropertyGroup>\n")
    unset(uv_section_${uv_section})
  endforeach ()
  set(uv_links "")
  foreach (uv_owner IN LISTS uv_owners)
    string(APPEND uv_links "        <ShareProperties subproxy=\"${uv_owner}\">\n")
    foreach (uv_kept IN ITEMS Input Visibility SelectMapper LISTS uv_entry_${uv_owner}_properties)
      if (NOT uv_kept IN_LIST uv_taken_${uv_owner})
        string(APPEND uv_links "          <Exception name=\"${uv_kept}\" />\n")
      endif ()
    endforeach ()
    string(APPEND uv_links "        </ShareProperties>\n")
    unset(uv_taken_${uv_owner})
  endforeach ()
  set(uv_subproxy_${uv_entry}
"      <RepresentationType subproxy=\"${uv_entry}\" text=\"${uv_entry_${uv_entry}_menu}\" />
      <SubProxy>
        <Proxy name=\"${uv_entry}\" proxygroup=\"representations\" proxyname=\"${uv_entry}\" />
        <ShareProperties subproxy=\"VolumeRepresentation\">
          <Exception name=\"Input\" />
          <Exception name=\"Visibility\" />
SELECT_MAPPER_EXCEPTION        </ShareProperties>
${uv_links}        <ExposedProperties>
${uv_exposed}        </ExposedProperties>
      </SubProxy>
")
endforeach ()

set(uv_menus "<ServerManagerConfiguration>\n  <!-- Generated by Plugin/Plugin.cmake from ${uv_representations_table}. -->\n")
string(APPEND uv_menus "  <ProxyGroup name=\"representations\">\n")
# UniformGridRepresentation's volume subproxy is ParaView's image volume representation, which has
# no SelectMapper property to keep out of the sharing.
foreach (uv_data_representation UnstructuredGridRepresentation StructuredGridRepresentation UniformGridRepresentation)
  string(APPEND uv_menus "    <Extension name=\"${uv_data_representation}\">\n")
  set(uv_select_mapper "          <Exception name=\"SelectMapper\" />\n")
  if (uv_data_representation STREQUAL "UniformGridRepresentation")
    set(uv_select_mapper "")
  endif ()
  foreach (uv_entry IN LISTS uv_entries)
    string(REPLACE "SELECT_MAPPER_EXCEPTION" "${uv_select_mapper}" uv_subproxy "${uv_subproxy_${uv_entry}}")
    string(APPEND uv_menus "${uv_subproxy}")
  endforeach ()
  string(APPEND uv_menus "    </Extension>\n")
endforeach ()
string(APPEND uv_menus "  </ProxyGroup>\n</ServerManagerConfiguration>\n")
set(uv_menus_xml "${CMAKE_BINARY_DIR}/UnstructuredVolumeRepresentationMenus.xml")
file(WRITE "${uv_menus_xml}.in" "${uv_menus}")
configure_file("${uv_menus_xml}.in" "${uv_menus_xml}" COPYONLY) # rewritten only when it changes

paraview_add_plugin(UnstructuredVolume
  VERSION "${PROJECT_VERSION}"
  MODULES UnstructuredVolume::vtkUnstructuredVolume UnstructuredVolume::vtkUnstructuredVolumeParaView
  MODULE_FILES "${uv_staged_module_dir}/vtk.module" "${UV_SOURCE_DIR}/Plugin/ParaView/vtk.module"
  SERVER_MANAGER_XML
    "${UV_SOURCE_DIR}/Plugin/UnstructuredVolumeFilters.xml"
    "${uv_representations_xml}"
    "${uv_menus_xml}")
