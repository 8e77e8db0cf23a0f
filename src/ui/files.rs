//! Saving and opening files: a download or the browser's file dialog on the web,
//! a file in the working folder on the desktop.

/// Pending text of a file the user picked, filled in later by the browser (an
/// `Err` holds why it could not be read).
pub type PendingFile = std::rc::Rc<std::cell::RefCell<Option<Result<String, String>>>>;

use crate::tr;

/// A file that could not be saved or opened; the message says what the user can
/// do about it. Nothing in Shoal changes when one of these happens.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FileError {
    /// The browser refused to start the download.
    Download(String),
    /// The desktop app could not write the file.
    Write { name: String, reason: String },
    /// The browser's file dialog did not open.
    Dialog(String),
    /// The chosen file could not be read.
    Read { name: String, reason: String },
}

impl std::fmt::Display for FileError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let text = match self {
            Self::Download(reason) => tr!("files-download-failed", reason = reason),
            Self::Write { name, reason } => {
                tr!("files-write-failed", name = name, reason = reason)
            }
            Self::Dialog(reason) => tr!("files-dialog-failed", reason = reason),
            Self::Read { name, reason } => tr!("files-read-failed", name = name, reason = reason),
        };
        f.write_str(&text)
    }
}

impl std::error::Error for FileError {}

/// Saves `text` as `name` and returns the message for the user. `what_next` is
/// added to it on the web (for example "open it with a spreadsheet").
pub fn save_text_file(
    name: &str,
    mime: &str,
    text: &str,
    what_next: Option<&str>,
) -> Result<String, FileError> {
    #[cfg(target_arch = "wasm32")]
    {
        crate::web::download_text(name, mime, text)
            .map(|()| match what_next {
                Some(next) => tr!("files-downloading-next", name = name, next = next),
                None => tr!("files-downloading", name = name),
            })
            .map_err(FileError::Download)
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        let _ = (mime, what_next);
        std::fs::write(name, text)
            .map(|()| tr!("files-saved", name = name))
            .map_err(|err| FileError::Write {
                name: name.to_owned(),
                reason: err.to_string(),
            })
    }
}

/// Asks for a text file: the browser's file dialog (the text arrives in
/// `pending` in a later frame, and `ctx` is asked to repaint); natively
/// `native_name` in the working folder, at once.
pub fn open_text_file(
    accept: &str,
    native_name: &str,
    pending: &PendingFile,
    ctx: &eframe::egui::Context,
) -> Result<(), FileError> {
    #[cfg(target_arch = "wasm32")]
    {
        let _ = native_name;
        let ctx = ctx.clone();
        crate::web::pick_text_file(accept, pending.clone(), move || {
            ctx.request_repaint();
        })
        .map_err(FileError::Dialog)
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        let _ = (accept, ctx);
        let text = std::fs::read_to_string(native_name).map_err(|err| {
            FileError::Read {
                name: native_name.to_owned(),
                reason: err.to_string(),
            }
            .to_string()
        });
        *pending.borrow_mut() = Some(text);
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_that_cannot_be_written_or_read_says_which_and_why() {
        let err = save_text_file("/no/such/folder/shoal.csv", "text/csv", "a,b", None)
            .expect_err("the folder does not exist");
        assert!(matches!(&err, FileError::Write { name, .. } if name.contains("shoal.csv")));
        assert!(
            err.to_string()
                .starts_with("Could not save /no/such/folder/shoal.csv: ")
        );

        let pending = PendingFile::default();
        let ctx = eframe::egui::Context::default();
        open_text_file(".json", "/no/such/file.json", &pending, &ctx).unwrap();
        let read = pending.borrow_mut().take().expect("read at once natively");
        assert!(
            read.unwrap_err()
                .starts_with("could not read /no/such/file.json: ")
        );
    }
}
