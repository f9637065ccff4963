//! The CSV's fingerprint in its sidecar (issue 13, "Guard a recording's CSV + sidecar
//! pair"): `csv_sha256` (the SHA-256 of the CSV's bytes, 64 lowercase hex digits) and
//! `csv_rows` (its data rows: lines after the header that are neither blank nor `#`
//! comments). The writer puts both in every sidecar it writes; [`verify`] refuses a pair
//! whose CSV does not match them. A sidecar without them (a bench's own) is accepted.

use sha2::{Digest, Sha256};

use super::error::{Reason, RecordingError};

/// What a sidecar records about its CSV.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CsvCheck {
    /// SHA-256 of the CSV's bytes, lowercase hex (`csv_sha256`).
    pub sha256: String,
    /// Data rows of the CSV (`csv_rows`).
    pub rows: u64,
}

impl CsvCheck {
    /// The fingerprint of a CSV's bytes.
    pub fn of(csv: &[u8]) -> CsvCheck {
        let digest = Sha256::digest(csv);
        let sha256 = digest.iter().map(|b| format!("{b:02x}")).collect();
        let lines = csv
            .split(|&b| b == b'\n')
            .filter(|l| !l.starts_with(b"#") && !l.iter().all(u8::is_ascii_whitespace))
            .count();
        CsvCheck {
            sha256,
            rows: lines.saturating_sub(1) as u64,
        }
    }

    /// Whether `text` is a valid `csv_sha256` value.
    pub fn valid_hash(text: &str) -> bool {
        text.len() == 64 && text.bytes().all(|b| b.is_ascii_hexdigit())
    }
}

/// Refuses a CSV (`csv_file`, bytes `csv`) that does not match what its sidecar
/// (`sidecar_file`) recorded; the error names both files.
pub fn verify(
    recorded: &CsvCheck,
    csv: &[u8],
    csv_file: &str,
    sidecar_file: &str,
) -> Result<(), RecordingError> {
    let found = CsvCheck::of(csv);
    if found.rows == recorded.rows && found.sha256.eq_ignore_ascii_case(&recorded.sha256) {
        return Ok(());
    }
    let what = if found.rows != recorded.rows {
        format!(
            "{sidecar_file} records {} rows (`csv_rows`), the CSV has {}",
            recorded.rows, found.rows
        )
    } else {
        format!("its SHA-256 differs from `csv_sha256` in {sidecar_file}")
    };
    Err(RecordingError::new(
        csv_file,
        Reason::Inconsistent(format!(
            "the CSV was changed after its sidecar was written, or the write was interrupted: {what}; write the pair again, or delete `csv_sha256` and `csv_rows` from {sidecar_file} to accept this CSV as it is"
        )),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fingerprint_counts_data_rows_and_hashes_bytes() {
        let text = b"# bench\ntime_s,crank_rpm\n0,1\n\n0.1,2\n";
        let check = CsvCheck::of(text);
        assert_eq!(check.rows, 2);
        // SHA-256 of the empty input, a published test vector.
        assert_eq!(
            CsvCheck::of(b"").sha256,
            "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855"
        );
        assert!(CsvCheck::valid_hash(&check.sha256));
        assert!(verify(&check, text, "a.csv", "a.toml").is_ok());
        let e = verify(&check, b"time_s,crank_rpm\n0,1\n", "a.csv", "a.toml").unwrap_err();
        let text = e.to_string();
        assert!(
            text.starts_with("a.csv: the CSV was changed after its sidecar"),
            "{text}"
        );
        assert!(text.contains("a.toml records 2 rows"), "{text}");
        // Same rows, one digit changed.
        let e = verify(
            &check,
            b"# bench\ntime_s,crank_rpm\n0,1\n\n0.1,3\n",
            "a.csv",
            "a.toml",
        );
        assert!(e.unwrap_err().to_string().contains("SHA-256 differs"));
    }
}
