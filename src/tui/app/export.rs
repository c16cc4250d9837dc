//! Export from the workbench (issue 30 item 20): `x` the focused pane's data, `X` the
//! whole report, each through a path prompt that works like the deck's save-as prompt
//! (an existing file is replaced only when the user says so). Apart because it is its
//! own small flow: prompt → check the target → ask → write.

use std::path::PathBuf;

use super::{App, Command, ExportWhat, Mode, PromptKind};
use crate::tui::export;

impl App {
    /// Opens the export prompt for `what`, offering a file beside the deck; when the
    /// focused pane has nothing to export, says why instead.
    pub(super) fn open_export_prompt(&mut self, what: ExportWhat) {
        let path = match what {
            ExportWhat::Pane => match export::pane_export(self) {
                Ok(e) => export::default_path(self, Some((self.focus, e.extension))),
                Err(why) => {
                    self.message = Some(why);
                    return;
                }
            },
            ExportWhat::Report => export::default_path(self, None),
        };
        self.mode = Mode::Prompt {
            kind: PromptKind::Export(what),
            buffer: path.display().to_string(),
        };
    }

    /// What to do once the user has chosen `path` for `what` (and, if it exists, agreed
    /// to replace it): the pane's contents as they are now, or the report job.
    pub(super) fn export_commands(&mut self, path: PathBuf, what: ExportWhat) -> Vec<Command> {
        match what {
            ExportWhat::Pane => match export::pane_export(self) {
                Ok(e) => vec![Command::WriteExport {
                    path,
                    contents: e.contents,
                    what: e.what,
                }],
                Err(why) => {
                    self.message = Some(why);
                    Vec::new()
                }
            },
            ExportWhat::Report => {
                let format = export::report_format_for(&path);
                self.message = Some(format!(
                    "writing the {} report to {}…",
                    export::format_name(format),
                    path.display()
                ));
                vec![Command::ExportReport {
                    path,
                    deck: Box::new(self.deck.clone()),
                    format,
                }]
            }
        }
    }

    /// The answer to "file exists": `y` writes, anything else goes back to the prompt
    /// to choose another name.
    pub(super) fn on_confirm_export(
        &mut self,
        yes: bool,
        path: PathBuf,
        what: ExportWhat,
    ) -> Vec<Command> {
        if yes {
            self.mode = Mode::Normal;
            self.export_commands(path, what)
        } else {
            self.mode = Mode::Prompt {
                kind: PromptKind::Export(what),
                buffer: path.display().to_string(),
            };
            Vec::new()
        }
    }
}
