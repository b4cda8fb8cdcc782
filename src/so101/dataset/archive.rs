//! The dataset as one `.zip`: every file stored (the parquet pages are snappy-compressed
//! already, the JSON is small), dated 1980-01-01 00:00 (the format's first date), permissions
//! 0644, in the order given; so the same files give the same bytes on every machine.

use std::io::{Cursor, Write};

use zip::write::SimpleFileOptions;
use zip::{CompressionMethod, DateTime, ZipWriter};

use super::error::DatasetError;

/// The zip of `files` (`(path in the archive, bytes)`).
pub fn zip(files: &[(String, Vec<u8>)]) -> Result<Vec<u8>, DatasetError> {
    let fail = |e: &dyn std::fmt::Display| DatasetError::Zip {
        detail: e.to_string(),
    };
    let options = SimpleFileOptions::default()
        .compression_method(CompressionMethod::Stored)
        .last_modified_time(DateTime::default())
        .unix_permissions(0o644);
    let mut writer = ZipWriter::new(Cursor::new(Vec::new()));
    for (name, bytes) in files {
        writer
            .start_file(name.as_str(), options)
            .map_err(|e| fail(&e))?;
        writer.write_all(bytes).map_err(|e| fail(&e))?;
    }
    let cursor = writer.finish().map_err(|e| fail(&e))?;
    Ok(cursor.into_inner())
}
