//! Parquet files as pyarrow writes them for LeRobot, from columns in memory: every field
//! `optional`, a list the three-level `LIST` (`repeated group list { optional element }`),
//! strings `BYTE_ARRAY` (`String`), snappy pages, the arrow schema in the footer
//! (`ARROW:schema`, [`super::arrow_schema`]) so fixed-size lists read back as
//! `fixed_size_list<…>[n]`, and any further footer metadata (pandas' for `tasks.parquet`).
//! One row group per slice of rows asked for (the data file: one per episode, as LeRobot
//! writes it).

use std::sync::Arc;

use parquet::basic::{Compression, LogicalType, Repetition, Type as Physical};
use parquet::column::writer::{ColumnWriter, ColumnWriterImpl};
use parquet::data_type::{ByteArray, DataType};
use parquet::errors::ParquetError;
use parquet::file::metadata::KeyValue;
use parquet::file::properties::WriterProperties;
use parquet::file::writer::SerializedFileWriter;
use parquet::schema::types::{Type, TypePtr};

use super::arrow_schema::{arrow_schema_base64, ArrowType};

/// A column's values.
#[derive(Debug, Clone, PartialEq)]
pub enum Values {
    /// `float` (arrow `float32`).
    Float32(Vec<f32>),
    /// `fixed_size_list<float>[width]`: `width` values per row, row after row.
    Float32Fixed { width: usize, values: Vec<f32> },
    /// `int64`.
    Int64(Vec<i64>),
    /// `bool`.
    Bool(Vec<bool>),
    /// `string`.
    Utf8(Vec<String>),
    /// `list<double>`, one list per row.
    Float64List(Vec<Vec<f64>>),
    /// `list<int64>`, one list per row.
    Int64List(Vec<Vec<i64>>),
    /// `list<string>`, one list per row.
    Utf8List(Vec<Vec<String>>),
}

impl Values {
    /// Rows held.
    pub fn rows(&self) -> usize {
        match self {
            Values::Float32(v) => v.len(),
            Values::Float32Fixed { width, values } => values.len() / (*width).max(1),
            Values::Int64(v) => v.len(),
            Values::Bool(v) => v.len(),
            Values::Utf8(v) => v.len(),
            Values::Float64List(v) => v.len(),
            Values::Int64List(v) => v.len(),
            Values::Utf8List(v) => v.len(),
        }
    }

    fn arrow_type(&self) -> ArrowType {
        match self {
            Values::Float32(_) => ArrowType::Float32,
            Values::Float32Fixed { width, .. } => ArrowType::Float32Fixed(*width),
            Values::Int64(_) => ArrowType::Int64,
            Values::Bool(_) => ArrowType::Bool,
            Values::Utf8(_) => ArrowType::Utf8,
            Values::Float64List(_) => ArrowType::Float64List,
            Values::Int64List(_) => ArrowType::Int64List,
            Values::Utf8List(_) => ArrowType::Utf8List,
        }
    }
}

/// One column: its name and its values (all columns of a file hold the same rows).
pub type Column = (String, Values);

/// The parquet schema of `columns`.
fn schema(columns: &[Column]) -> Result<TypePtr, ParquetError> {
    let mut fields = Vec::with_capacity(columns.len());
    for (name, values) in columns {
        let (physical, string) = match values.arrow_type() {
            ArrowType::Float32 | ArrowType::Float32Fixed(_) => (Physical::FLOAT, false),
            ArrowType::Int64 | ArrowType::Int64List => (Physical::INT64, false),
            ArrowType::Bool => (Physical::BOOLEAN, false),
            ArrowType::Utf8 | ArrowType::Utf8List => (Physical::BYTE_ARRAY, true),
            ArrowType::Float64List => (Physical::DOUBLE, false),
        };
        let list = values.arrow_type().is_list();
        let leaf = Type::primitive_type_builder(if list { "element" } else { name }, physical)
            .with_repetition(Repetition::OPTIONAL)
            .with_logical_type(string.then_some(LogicalType::String))
            .build()?;
        let field = if list {
            let repeated = Type::group_type_builder("list")
                .with_repetition(Repetition::REPEATED)
                .with_fields(vec![Arc::new(leaf)])
                .build()?;
            Type::group_type_builder(name)
                .with_repetition(Repetition::OPTIONAL)
                .with_logical_type(Some(LogicalType::List))
                .with_fields(vec![Arc::new(repeated)])
                .build()?
        } else {
            leaf
        };
        fields.push(Arc::new(field));
    }
    Ok(Arc::new(
        Type::group_type_builder("schema")
            .with_fields(fields)
            .build()?,
    ))
}

/// A parquet file of `columns`, a row group for each of `row_groups` (row counts summing to
/// the columns' rows), with `metadata` (key, value) in the footer after `ARROW:schema`.
pub fn parquet_file(
    columns: &[Column],
    row_groups: &[usize],
    metadata: &[(&str, String)],
) -> Result<Vec<u8>, ParquetError> {
    let arrow: Vec<(&str, ArrowType)> = columns
        .iter()
        .map(|(n, v)| (n.as_str(), v.arrow_type()))
        .collect();
    let pairs: Vec<(&str, &str)> = metadata.iter().map(|(k, v)| (*k, v.as_str())).collect();
    let mut key_values = vec![KeyValue::new(
        "ARROW:schema".to_string(),
        arrow_schema_base64(&arrow, &pairs),
    )];
    for (k, v) in metadata {
        key_values.push(KeyValue::new((*k).to_string(), v.clone()));
    }
    let props = WriterProperties::builder()
        .set_compression(Compression::SNAPPY)
        .set_key_value_metadata(Some(key_values))
        .build();
    let total: usize = row_groups.iter().sum();
    if let Some((name, _)) = columns.iter().find(|(_, v)| v.rows() != total) {
        return Err(ParquetError::General(format!("{name}: not {total} rows")));
    }
    let mut writer = SerializedFileWriter::new(Vec::new(), schema(columns)?, Arc::new(props))?;
    let mut start = 0;
    for &rows in row_groups {
        let end = start + rows;
        let mut group = writer.next_row_group()?;
        for (name, values) in columns {
            let Some(mut column) = group.next_column()? else {
                return Err(ParquetError::General(format!("{name}: no column writer")));
            };
            write_rows(column.untyped(), values, start..end)
                .map_err(|e| ParquetError::General(format!("{name}: {e}")))?;
            column.close()?;
        }
        group.close()?;
        start = end;
    }
    writer.into_inner()
}

/// Writes rows `rows` of `values` into the column writer of their type.
fn write_rows(
    writer: &mut ColumnWriter<'_>,
    values: &Values,
    rows: std::ops::Range<usize>,
) -> Result<(), ParquetError> {
    let n = rows.len();
    let present = vec![1i16; n];
    match (writer, values) {
        (ColumnWriter::FloatColumnWriter(w), Values::Float32(v)) => {
            scalars(w, slice(v, rows)?, &present)
        }
        (ColumnWriter::FloatColumnWriter(w), Values::Float32Fixed { width, values }) => {
            let flat = slice(values, rows.start * width..rows.end * width)?;
            let (def, rep) = fixed_levels(n, *width);
            w.write_batch(flat, Some(&def), Some(&rep)).map(drop)
        }
        (ColumnWriter::Int64ColumnWriter(w), Values::Int64(v)) => {
            scalars(w, slice(v, rows)?, &present)
        }
        (ColumnWriter::BoolColumnWriter(w), Values::Bool(v)) => {
            scalars(w, slice(v, rows)?, &present)
        }
        (ColumnWriter::ByteArrayColumnWriter(w), Values::Utf8(v)) => {
            let bytes: Vec<ByteArray> = slice(v, rows)?
                .iter()
                .map(|s| ByteArray::from(s.as_str()))
                .collect();
            scalars(w, &bytes, &present)
        }
        (ColumnWriter::DoubleColumnWriter(w), Values::Float64List(v)) => {
            lists(w, slice(v, rows)?, |x| *x)
        }
        (ColumnWriter::Int64ColumnWriter(w), Values::Int64List(v)) => {
            lists(w, slice(v, rows)?, |x| *x)
        }
        (ColumnWriter::ByteArrayColumnWriter(w), Values::Utf8List(v)) => {
            lists(w, slice(v, rows)?, |s| ByteArray::from(s.as_str()))
        }
        _ => Err(ParquetError::General(
            "values of another type than the column's".to_string(),
        )),
    }
}

fn slice<T>(v: &[T], range: std::ops::Range<usize>) -> Result<&[T], ParquetError> {
    v.get(range)
        .ok_or_else(|| ParquetError::General("fewer rows than the row groups".to_string()))
}

/// An optional scalar per row, all present.
fn scalars<T: DataType>(
    w: &mut ColumnWriterImpl<'_, T>,
    values: &[T::T],
    present: &[i16],
) -> Result<(), ParquetError> {
    w.write_batch(values, Some(present), None).map(drop)
}

/// The levels of `rows` lists of `width` present values: definition 3 (list, entry and
/// value present), repetition 0 at each list's first value and 1 after.
fn fixed_levels(rows: usize, width: usize) -> (Vec<i16>, Vec<i16>) {
    let def = vec![3i16; rows * width];
    let rep = (0..rows * width)
        .map(|i| i16::from(i % width != 0))
        .collect();
    (def, rep)
}

/// One list per row (an empty list is definition 1: the list present, no entry).
fn lists<T: DataType, S>(
    w: &mut ColumnWriterImpl<'_, T>,
    rows: &[Vec<S>],
    convert: impl Fn(&S) -> T::T,
) -> Result<(), ParquetError> {
    let (mut values, mut def, mut rep) = (Vec::new(), Vec::new(), Vec::new());
    for row in rows {
        if row.is_empty() {
            def.push(1);
            rep.push(0);
        }
        for (i, x) in row.iter().enumerate() {
            values.push(convert(x));
            def.push(3);
            rep.push(i16::from(i != 0));
        }
    }
    w.write_batch(&values, Some(&def), Some(&rep)).map(drop)
}
