#include "bearing/records/full_record_formats.h"

#ifdef BEARING_RECORDS_WITH_SNDFILE
#include "bearing/records/wav_record.h"
#endif
#ifdef BEARING_RECORDS_WITH_MATIO
#include "bearing/records/mat_record.h"
#endif
#ifdef BEARING_RECORDS_WITH_HDF5
#include "bearing/records/h5_record.h"
#endif

namespace bearing {

std::vector<RecordFormat> full_record_formats() {
  return {
#ifdef BEARING_RECORDS_WITH_SNDFILE
      {".wav", "WAV (libsndfile): integer PCM as fractions of full scale, float as stored",
       read_wav_record, "", false},
#else
      {".wav", "WAV (libsndfile)", nullptr,
       "this build cannot read .wav: libsndfile1-dev was not found at build time", false},
#endif
#ifdef BEARING_RECORDS_WITH_MATIO
      {".mat", "MATLAB 5, 7 and 7.3 (libmatio): the numeric vectors are channels", read_mat_record,
       "", false},
#else
      {".mat", "MATLAB (libmatio)", nullptr,
       "this build cannot read .mat: libmatio-dev was not found at build time", false},
#endif
#ifdef BEARING_RECORDS_WITH_HDF5
      {".h5", "HDF5 (--dataset; a rate attribute, a columns attribute)", read_h5_record, "", true},
      {".hdf5", "HDF5 (--dataset; a rate attribute, a columns attribute)", read_h5_record, "",
       true},
#else
      {".h5", "HDF5", nullptr,
       "this build cannot read .h5: libhdf5-dev was not found at build time", true},
      {".hdf5", "HDF5", nullptr,
       "this build cannot read .hdf5: libhdf5-dev was not found at build time", true},
#endif
  };
}

}  // namespace bearing
