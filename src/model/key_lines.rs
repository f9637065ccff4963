//! Line numbers for the model reader: byte offsets to 1-based lines, and the map from
//! key paths (`connection[2].stiffness`) to the lines they were written on.

use std::collections::HashMap;

use toml_edit::{Item, TableLike, Value};

use super::spanned::join;

/// Byte offsets where each line starts, to turn spans into 1-based line numbers.
pub(crate) struct Lines {
    starts: Vec<usize>,
}

impl Lines {
    /// Line starts of `text`.
    pub(crate) fn new(text: &str) -> Self {
        let starts = std::iter::once(0)
            .chain(text.match_indices('\n').map(|(i, _)| i + 1))
            .collect();
        Self { starts }
    }

    /// 1-based line of a byte offset.
    pub(crate) fn line_of(&self, offset: usize) -> usize {
        self.starts.partition_point(|&s| s <= offset).max(1)
    }
}

/// Key path → line of every table header, key and array element in the document.
pub(crate) struct KeyLines {
    lines: HashMap<String, usize>,
}

impl KeyLines {
    /// Walks the whole document once.
    pub(crate) fn new(root: &dyn TableLike, text: &Lines) -> Self {
        let mut me = Self {
            lines: HashMap::new(),
        };
        me.table(root, "", text);
        me
    }

    fn record(&mut self, path: String, span: Option<std::ops::Range<usize>>, text: &Lines) {
        if let Some(span) = span {
            self.lines.entry(path).or_insert(text.line_of(span.start));
        }
    }

    fn table(&mut self, table: &dyn TableLike, path: &str, text: &Lines) {
        for (key, item) in table.iter() {
            let sub = join(path, key);
            self.record(sub.clone(), table.key(key).and_then(|k| k.span()), text);
            self.item(item, &sub, text);
        }
    }

    fn item(&mut self, item: &Item, path: &str, text: &Lines) {
        match item {
            Item::Table(t) => {
                self.record(path.to_string(), t.span(), text);
                self.table(t, path, text);
            }
            Item::ArrayOfTables(a) => {
                for (i, t) in a.iter().enumerate() {
                    let sub = format!("{path}[{i}]");
                    self.record(sub.clone(), t.span(), text);
                    self.table(t, &sub, text);
                }
            }
            Item::Value(v) => self.value(v, path, text),
            Item::None => {}
        }
    }

    fn value(&mut self, value: &Value, path: &str, text: &Lines) {
        self.record(path.to_string(), value.span(), text);
        match value {
            Value::Array(a) => {
                for (i, v) in a.iter().enumerate() {
                    self.value(v, &format!("{path}[{i}]"), text);
                }
            }
            Value::InlineTable(t) => self.table(t, path, text),
            _ => {}
        }
    }

    /// Line of a key path, or of the nearest enclosing table or array that has one.
    pub(crate) fn line(&self, path: &str) -> Option<usize> {
        let mut path = path;
        loop {
            if let Some(&line) = self.lines.get(path) {
                return Some(line);
            }
            let cut = path.rfind(['.', '['])?;
            path = &path[..cut];
        }
    }
}
