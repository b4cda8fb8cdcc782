//! The `ARROW:schema` footer entry of a parquet file: the arrow schema as an Arrow IPC
//! `Schema` message (a FlatBuffer, `format/Message.fbs` and `format/Schema.fbs` of Apache
//! Arrow), after the continuation marker `0xFFFFFFFF` and its little-endian length, in
//! standard base64, as pyarrow and arrow-rs write it. pyarrow reads a parquet file's column
//! types from it: without it a `fixed_size_list<float>[6]` column would read back as
//! `list<float>`.
//!
//! The FlatBuffer is laid out front to back: each table's vtable just before it, every child
//! (string, vector, table) after the offset that points to it, every scalar aligned to its
//! size, the whole padded to 8 bytes.

/// A column's arrow type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ArrowType {
    /// `float`.
    Float32,
    /// `fixed_size_list<item: float>[n]`.
    Float32Fixed(usize),
    /// `int64`.
    Int64,
    /// `bool`.
    Bool,
    /// `string`.
    Utf8,
    /// `list<item: double>`.
    Float64List,
    /// `list<item: int64>`.
    Int64List,
    /// `list<item: string>`.
    Utf8List,
}

impl ArrowType {
    /// Whether the column is a list (a parquet `LIST` group).
    pub fn is_list(self) -> bool {
        matches!(
            self,
            ArrowType::Float32Fixed(_)
                | ArrowType::Float64List
                | ArrowType::Int64List
                | ArrowType::Utf8List
        )
    }
}

/// `Type` union tags of `Schema.fbs`.
const TYPE_INT: u8 = 2;
const TYPE_FLOATING_POINT: u8 = 3;
const TYPE_UTF8: u8 = 5;
const TYPE_BOOL: u8 = 6;
const TYPE_LIST: u8 = 12;
const TYPE_FIXED_SIZE_LIST: u8 = 16;
/// `Precision` of `FloatingPoint`.
const PRECISION_SINGLE: i16 = 1;
const PRECISION_DOUBLE: i16 = 2;
/// `MetadataVersion.V5`.
const METADATA_V5: i16 = 4;
/// `MessageHeader.Schema`.
const HEADER_SCHEMA: u8 = 1;

/// A scalar type of an element or a scalar column.
#[derive(Clone, Copy)]
enum Leaf {
    Float32,
    Float64,
    Int64,
    Bool,
    Utf8,
}

/// The base64 `ARROW:schema` of columns `(name, type)`, all nullable, with the schema's
/// metadata `(key, value)` (pyarrow takes a file's schema metadata from here when the entry
/// is present: pandas' metadata must be in it too).
pub fn arrow_schema_base64(columns: &[(&str, ArrowType)], metadata: &[(&str, &str)]) -> String {
    let message = schema_message(columns, metadata);
    let mut framed = Vec::with_capacity(message.len() + 8);
    framed.extend_from_slice(&[0xFF; 4]);
    framed.extend_from_slice(&(message.len() as u32).to_le_bytes());
    framed.extend_from_slice(&message);
    base64(&framed)
}

/// One inline field of a table: its id in the vtable and its value.
#[derive(Clone, Copy)]
enum Slot {
    U8(u8),
    I16(i16),
    I32(i32),
    I64(i64),
    /// An offset to a child written later (patched by [`Builder::patch`]).
    Offset,
}

impl Slot {
    fn size(self) -> usize {
        match self {
            Slot::U8(_) => 1,
            Slot::I16(_) => 2,
            Slot::I32(_) | Slot::Offset => 4,
            Slot::I64(_) => 8,
        }
    }
}

/// A FlatBuffer written front to back.
struct Builder {
    buf: Vec<u8>,
}

impl Builder {
    fn pad_to(&mut self, align: usize) {
        while self.buf.len() % align != 0 {
            self.buf.push(0);
        }
    }

    /// Writes a table (its vtable first) of `(field id, value)`: where the table starts and
    /// the positions of its [`Slot::Offset`] fields, in order.
    fn table(&mut self, fields: &[(u16, Slot)]) -> (usize, Vec<usize>) {
        let slots = fields.iter().map(|f| f.0 + 1).max().unwrap_or(0);
        let vtable_len = 4 + 2 * usize::from(slots);
        // The table's inline part: the vtable's soffset, then each field at its alignment.
        let mut layout = Vec::with_capacity(fields.len());
        let mut at = 4usize;
        for (id, slot) in fields {
            at = at.next_multiple_of(slot.size());
            layout.push((*id, *slot, at));
            at += slot.size();
        }
        let table_len = at.next_multiple_of(4);
        // The table starts 8-aligned (its i64 fields are at multiples of 8 in it).
        self.pad_to(2);
        let mut vtable_at = self.buf.len();
        while (vtable_at + vtable_len) % 8 != 0 {
            vtable_at += 2;
        }
        self.buf.resize(vtable_at, 0);
        let table_at = vtable_at + vtable_len;
        let mut vtable = vec![0u16; usize::from(slots)];
        for (id, _, offset) in &layout {
            vtable[usize::from(*id)] = *offset as u16;
        }
        self.buf
            .extend_from_slice(&(vtable_len as u16).to_le_bytes());
        self.buf
            .extend_from_slice(&(table_len as u16).to_le_bytes());
        for v in vtable {
            self.buf.extend_from_slice(&v.to_le_bytes());
        }
        self.buf.resize(table_at + table_len, 0);
        self.buf[table_at..table_at + 4].copy_from_slice(&(vtable_len as i32).to_le_bytes());
        let mut offsets = Vec::new();
        for (_, slot, offset) in layout {
            let p = table_at + offset;
            match slot {
                Slot::U8(v) => self.buf[p] = v,
                Slot::I16(v) => self.buf[p..p + 2].copy_from_slice(&v.to_le_bytes()),
                Slot::I32(v) => self.buf[p..p + 4].copy_from_slice(&v.to_le_bytes()),
                Slot::I64(v) => self.buf[p..p + 8].copy_from_slice(&v.to_le_bytes()),
                Slot::Offset => offsets.push(p),
            }
        }
        (table_at, offsets)
    }

    /// Points the offset at `slot` to `target` (written after it).
    fn patch(&mut self, slot: usize, target: usize) {
        let delta = (target - slot) as u32;
        self.buf[slot..slot + 4].copy_from_slice(&delta.to_le_bytes());
    }

    /// A string for the offset at `slot`.
    fn string(&mut self, slot: usize, s: &str) {
        self.pad_to(4);
        let at = self.buf.len();
        self.patch(slot, at);
        self.buf.extend_from_slice(&(s.len() as u32).to_le_bytes());
        self.buf.extend_from_slice(s.as_bytes());
        self.buf.push(0);
    }

    /// A vector of `n` offsets (to tables written after it) for the offset at `slot`: the
    /// positions of its elements.
    fn offsets(&mut self, slot: usize, n: usize) -> Vec<usize> {
        self.pad_to(4);
        let at = self.buf.len();
        self.patch(slot, at);
        self.buf.extend_from_slice(&(n as u32).to_le_bytes());
        let first = self.buf.len();
        self.buf.resize(first + 4 * n, 0);
        (0..n).map(|i| first + 4 * i).collect()
    }

    /// A table for the offset at `slot`: the positions of its offset fields.
    fn child(&mut self, slot: usize, fields: &[(u16, Slot)]) -> Vec<usize> {
        let (at, offsets) = self.table(fields);
        self.patch(slot, at);
        offsets
    }

    /// A `Field` (name, nullable, type, children) for the offset at `slot`.
    fn field(&mut self, slot: usize, name: &str, ty: ArrowType) {
        let (list, leaf) = match ty {
            ArrowType::Float32 => (None, Leaf::Float32),
            ArrowType::Float32Fixed(n) => (Some(Some(n)), Leaf::Float32),
            ArrowType::Int64 => (None, Leaf::Int64),
            ArrowType::Bool => (None, Leaf::Bool),
            ArrowType::Utf8 => (None, Leaf::Utf8),
            ArrowType::Float64List => (Some(None), Leaf::Float64),
            ArrowType::Int64List => (Some(None), Leaf::Int64),
            ArrowType::Utf8List => (Some(None), Leaf::Utf8),
        };
        let Some(size) = list else {
            self.leaf_field(slot, name, leaf);
            return;
        };
        let type_tag = if size.is_some() {
            TYPE_FIXED_SIZE_LIST
        } else {
            TYPE_LIST
        };
        let at = self.child(slot, &field_slots(type_tag));
        self.string(at[0], name);
        match size {
            Some(n) => self.child(at[1], &[(0, Slot::I32(n as i32))]),
            None => self.child(at[1], &[]),
        };
        let item = self.offsets(at[2], 1);
        self.leaf_field(item[0], "item", leaf);
    }

    /// A `Field` of a scalar type (no children) for the offset at `slot`.
    fn leaf_field(&mut self, slot: usize, name: &str, leaf: Leaf) {
        let type_tag = match leaf {
            Leaf::Float32 | Leaf::Float64 => TYPE_FLOATING_POINT,
            Leaf::Int64 => TYPE_INT,
            Leaf::Bool => TYPE_BOOL,
            Leaf::Utf8 => TYPE_UTF8,
        };
        let at = self.child(slot, &field_slots(type_tag));
        self.string(at[0], name);
        match leaf {
            Leaf::Float32 => self.child(at[1], &[(0, Slot::I16(PRECISION_SINGLE))]),
            Leaf::Float64 => self.child(at[1], &[(0, Slot::I16(PRECISION_DOUBLE))]),
            Leaf::Int64 => self.child(at[1], &[(0, Slot::I32(64)), (1, Slot::U8(1))]),
            Leaf::Bool | Leaf::Utf8 => self.child(at[1], &[]),
        };
        self.offsets(at[2], 0);
    }
}

/// A nullable `Field`'s inline slots: name (offset), nullable, type tag, type (offset),
/// children (offset).
fn field_slots(type_tag: u8) -> [(u16, Slot); 5] {
    [
        (0, Slot::Offset),
        (1, Slot::U8(1)),
        (2, Slot::U8(type_tag)),
        (3, Slot::Offset),
        (5, Slot::Offset),
    ]
}

/// The `Message` FlatBuffer holding the `Schema` of `columns` and `metadata`.
fn schema_message(columns: &[(&str, ArrowType)], metadata: &[(&str, &str)]) -> Vec<u8> {
    let mut b = Builder {
        buf: vec![0; 4], // the root offset, to the message table
    };
    let (message_at, message) = b.table(&[
        (0, Slot::I16(METADATA_V5)),
        (1, Slot::U8(HEADER_SCHEMA)),
        (2, Slot::Offset),
        (3, Slot::I64(0)),
    ]);
    b.patch(0, message_at);
    let schema = b.child(
        message[0],
        &[(0, Slot::I16(0)), (1, Slot::Offset), (2, Slot::Offset)],
    );
    let slots = b.offsets(schema[0], columns.len());
    for (slot, (name, ty)) in slots.into_iter().zip(columns) {
        b.field(slot, name, *ty);
    }
    let pairs = b.offsets(schema[1], metadata.len());
    for (slot, (key, value)) in pairs.into_iter().zip(metadata) {
        let at = b.child(slot, &[(0, Slot::Offset), (1, Slot::Offset)]);
        b.string(at[0], key);
        b.string(at[1], value);
    }
    b.pad_to(8);
    b.buf
}

/// Standard base64 with `=` padding.
fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for i in 0..4 {
            if i <= chunk.len() {
                out.push(char::from(ALPHABET[(n >> (18 - 6 * i)) as usize & 63]));
            } else {
                out.push('=');
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    #[cfg(target_arch = "wasm32")]
    use wasm_bindgen_test::wasm_bindgen_test as test;

    use super::base64;

    #[test]
    fn base64_pads_as_the_standard_says() {
        assert_eq!(base64(b""), "");
        assert_eq!(base64(b"f"), "Zg==");
        assert_eq!(base64(b"fo"), "Zm8=");
        assert_eq!(base64(b"foo"), "Zm9v");
        assert_eq!(base64(b"foobar"), "Zm9vYmFy");
    }
}
