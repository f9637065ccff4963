//! Helpers for the model reader: typed access to TOML tables, with key paths for errors.

use toml_edit::{Item, TableLike, Value};

use super::error::ModelError;

/// `path.key`, or `key` at the top level.
pub(crate) fn join(path: &str, key: &str) -> String {
    if path.is_empty() {
        key.to_string()
    } else {
        format!("{path}.{key}")
    }
}

/// What a TOML item is, for "expected …, found …" messages.
fn found(name: &str) -> String {
    let article = if name.starts_with(['a', 'i']) {
        "an"
    } else {
        "a"
    };
    format!("{article} {name}")
}

/// A wrong-type error at `path`.
pub(crate) fn wrong_type(path: &str, expected: &str, item: &Item) -> ModelError {
    ModelError::at(
        path,
        format!("expected {expected}, found {}", found(item.type_name())),
    )
}

/// A number (TOML integer or float) as f64.
pub(crate) fn item_f64(item: &Item, path: &str) -> Result<f64, ModelError> {
    match (item.as_float(), item.as_integer()) {
        (Some(x), _) => Ok(x),
        (None, Some(i)) => Ok(i as f64),
        _ => Err(wrong_type(path, "a number", item)),
    }
}

/// A number from an array element.
fn value_f64(value: &Value, path: &str) -> Result<f64, ModelError> {
    match (value.as_float(), value.as_integer()) {
        (Some(x), _) => Ok(x),
        (None, Some(i)) => Ok(i as f64),
        _ => Err(ModelError::at(
            path,
            format!("expected a number, found {}", found(value.type_name())),
        )),
    }
}

/// A list of numbers.
pub(crate) fn item_f64s(item: &Item, path: &str) -> Result<Vec<f64>, ModelError> {
    let array = item
        .as_array()
        .ok_or_else(|| wrong_type(path, "a list of numbers", item))?;
    array
        .iter()
        .enumerate()
        .map(|(i, v)| value_f64(v, &format!("{path}[{i}]")))
        .collect()
}

/// A table (`[a]`, `[[a]]` entry or inline `{ … }`) with its key path.
pub(crate) struct Tab<'a> {
    table: &'a dyn TableLike,
    /// Key path of the table, e.g. `connection[2]` or `engine.pressure`.
    pub(crate) path: String,
}

impl<'a> Tab<'a> {
    /// Wraps a table at `path`.
    pub(crate) fn new(table: &'a dyn TableLike, path: impl Into<String>) -> Self {
        Self {
            table,
            path: path.into(),
        }
    }

    /// Key path of `key` in this table.
    pub(crate) fn key(&self, key: &str) -> String {
        join(&self.path, key)
    }

    /// Rejects keys not in `allowed`.
    pub(crate) fn allow(&self, allowed: &[&str]) -> Result<(), ModelError> {
        match self.table.iter().find(|(k, _)| !allowed.contains(k)) {
            None => Ok(()),
            Some((k, _)) => Err(ModelError::at(
                self.key(k),
                format!(
                    "unknown key `{k}` (known keys here: {})",
                    allowed.join(", ")
                ),
            )),
        }
    }

    /// The item at `key`, if present.
    pub(crate) fn get(&self, key: &str) -> Option<&'a Item> {
        self.table.get(key).filter(|i| !i.is_none())
    }

    /// The item at `key`, or a missing-key error.
    pub(crate) fn req(&self, key: &str) -> Result<&'a Item, ModelError> {
        self.get(key)
            .ok_or_else(|| ModelError::at(self.key(key), format!("missing required key `{key}`")))
    }

    /// An optional number.
    pub(crate) fn opt_f64(&self, key: &str) -> Result<Option<f64>, ModelError> {
        self.get(key)
            .map(|i| item_f64(i, &self.key(key)))
            .transpose()
    }

    /// A required number.
    pub(crate) fn f64(&self, key: &str) -> Result<f64, ModelError> {
        item_f64(self.req(key)?, &self.key(key))
    }

    /// A number with a default.
    pub(crate) fn f64_or(&self, key: &str, default: f64) -> Result<f64, ModelError> {
        Ok(self.opt_f64(key)?.unwrap_or(default))
    }

    /// An optional list of numbers.
    pub(crate) fn opt_f64s(&self, key: &str) -> Result<Option<Vec<f64>>, ModelError> {
        self.get(key)
            .map(|i| item_f64s(i, &self.key(key)))
            .transpose()
    }

    /// A required list of numbers.
    pub(crate) fn f64s(&self, key: &str) -> Result<Vec<f64>, ModelError> {
        item_f64s(self.req(key)?, &self.key(key))
    }

    /// An optional list of exactly `N` numbers.
    pub(crate) fn opt_array<const N: usize>(
        &self,
        key: &str,
    ) -> Result<Option<[f64; N]>, ModelError> {
        let Some(values) = self.opt_f64s(key)? else {
            return Ok(None);
        };
        let n = values.len();
        values.try_into().map(Some).map_err(|_| {
            ModelError::at(
                self.key(key),
                format!("expected a list of {N} numbers, found {n}"),
            )
        })
    }

    /// An optional non-negative integer that fits in u32.
    pub(crate) fn opt_u32(&self, key: &str) -> Result<Option<u32>, ModelError> {
        let Some(item) = self.get(key) else {
            return Ok(None);
        };
        let path = self.key(key);
        let i = item
            .as_integer()
            .ok_or_else(|| wrong_type(&path, "an integer", item))?;
        u32::try_from(i).map(Some).map_err(|_| {
            ModelError::at(path, format!("expected a non-negative integer, found {i}"))
        })
    }

    /// A required non-negative integer.
    pub(crate) fn u32(&self, key: &str) -> Result<u32, ModelError> {
        self.req(key)?;
        self.opt_u32(key).map(|v| v.unwrap_or_default())
    }

    /// An optional string.
    pub(crate) fn opt_str(&self, key: &str) -> Result<Option<String>, ModelError> {
        self.get(key)
            .map(|i| {
                i.as_str()
                    .map(str::to_string)
                    .ok_or_else(|| wrong_type(&self.key(key), "a string", i))
            })
            .transpose()
    }

    /// An optional sub-table (`[a.b]` or inline `b = { … }`).
    pub(crate) fn opt_table(&self, key: &str) -> Result<Option<Tab<'a>>, ModelError> {
        let path = self.key(key);
        self.get(key)
            .map(|i| as_table(i, &path).map(|t| Tab::new(t, path.clone())))
            .transpose()
    }

    /// A list of tables (`[[a]]` or an array of inline tables); empty when absent.
    pub(crate) fn list(&self, key: &str) -> Result<Vec<Tab<'a>>, ModelError> {
        match self.get(key) {
            None => Ok(Vec::new()),
            Some(item) => table_list(item, &self.key(key)),
        }
    }

    /// A required string.
    pub(crate) fn str(&self, key: &str) -> Result<String, ModelError> {
        self.req(key)?;
        self.opt_str(key).map(|v| v.unwrap_or_default())
    }
}

/// The tables of a list: `[[a]]` entries or an array of inline tables.
pub(crate) fn table_list<'a>(item: &'a Item, path: &str) -> Result<Vec<Tab<'a>>, ModelError> {
    if let Some(aot) = item.as_array_of_tables() {
        return Ok(aot
            .iter()
            .enumerate()
            .map(|(i, t)| Tab::new(t, format!("{path}[{i}]")))
            .collect());
    }
    let array = item
        .as_array()
        .ok_or_else(|| wrong_type(path, "a list of tables", item))?;
    array
        .iter()
        .enumerate()
        .map(|(i, v)| {
            let sub = format!("{path}[{i}]");
            match v.as_inline_table() {
                Some(t) => Ok(Tab::new(t, sub)),
                None => Err(ModelError::at(
                    sub,
                    format!("expected a table, found {}", found(v.type_name())),
                )),
            }
        })
        .collect()
}

/// An item that must be a table (`[a]` or inline).
pub(crate) fn as_table<'a>(item: &'a Item, path: &str) -> Result<&'a dyn TableLike, ModelError> {
    item.as_table_like()
        .ok_or_else(|| wrong_type(path, "a table", item))
}
