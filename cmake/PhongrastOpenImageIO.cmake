# phongrast_find_openimageio(): find_package(OpenImageIO) plus the Debian 12 fix.
#
# Debian's OpenImageIO config lists /usr/include/opencv4 in the include
# directories of OpenImageIO::OpenImageIO even when libopencv-dev is not
# installed, and CMake then refuses any target that links it ("includes
# non-existent path"). phongrast does not use OpenCV, so the missing entry is
# dropped right after find_package. Self-contained on purpose: the installed
# package config includes this file too.
include_guard(GLOBAL)

macro(phongrast_find_openimageio)
  if(NOT TARGET OpenImageIO::OpenImageIO)
    find_package(OpenImageIO CONFIG REQUIRED ${ARGN})
  endif()
  foreach(_phongrast_oiio_target IN ITEMS OpenImageIO::OpenImageIO OpenImageIO::OpenImageIO_Util)
    if(TARGET ${_phongrast_oiio_target})
      foreach(_phongrast_oiio_property IN ITEMS INTERFACE_INCLUDE_DIRECTORIES
                                                INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
        get_target_property(_phongrast_oiio_dirs ${_phongrast_oiio_target} ${_phongrast_oiio_property})
        if(_phongrast_oiio_dirs)
          set(_phongrast_oiio_kept "")
          foreach(_phongrast_oiio_dir IN LISTS _phongrast_oiio_dirs)
            # Keep generator expressions and folders that exist; drop the rest.
            if(_phongrast_oiio_dir MATCHES "^\\$<" OR EXISTS "${_phongrast_oiio_dir}")
              list(APPEND _phongrast_oiio_kept "${_phongrast_oiio_dir}")
            endif()
          endforeach()
          set_target_properties(${_phongrast_oiio_target} PROPERTIES
                                ${_phongrast_oiio_property} "${_phongrast_oiio_kept}")
        endif()
      endforeach()
    endif()
  endforeach()
  unset(_phongrast_oiio_target)
  unset(_phongrast_oiio_property)
  unset(_phongrast_oiio_dirs)
  unset(_phongrast_oiio_dir)
  unset(_phongrast_oiio_kept)
endmacro()
