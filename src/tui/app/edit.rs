//! Changing the deck and typing text: editing a field in place (cursor, choices,
//! validation on commit), undo and redo, searching the fields, and the save-as/open path
//! prompt. Apart because these are the transitions that change the deck or what is typed.

use std::path::PathBuf;

use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

use super::{App, Command, Mode, PromptKind};

impl App {
    pub(super) fn open_prompt(&mut self, kind: PromptKind) {
        let buffer = match (kind, &self.path) {
            (PromptKind::SaveAs, Some(p)) => p.display().to_string(),
            (PromptKind::SaveAs, None) => "deck.toml".to_string(),
            (PromptKind::Open | PromptKind::Baseline | PromptKind::Export(_), _) => String::new(),
        };
        self.mode = Mode::Prompt { kind, buffer };
    }

    pub(super) fn on_edit_key(
        &mut self,
        key: KeyEvent,
        mut buffer: String,
        mut cursor: usize,
        error: Option<String>,
    ) -> Vec<Command> {
        let byte_at = |s: &str, c: usize| s.char_indices().nth(c).map_or(s.len(), |(i, _)| i);
        match key.code {
            KeyCode::Esc => {
                self.mode = Mode::Normal;
                return Vec::new();
            }
            KeyCode::Char('c') if key.modifiers.contains(KeyModifiers::CONTROL) => {
                self.mode = Mode::Normal;
                return Vec::new();
            }
            KeyCode::Enter => return self.commit_edit(buffer),
            KeyCode::Char(ch) if !key.modifiers.contains(KeyModifiers::CONTROL) => {
                let at = byte_at(&buffer, cursor);
                buffer.insert(at, ch);
                cursor += 1;
            }
            KeyCode::Backspace if cursor > 0 => {
                let at = byte_at(&buffer, cursor - 1);
                buffer.remove(at);
                cursor -= 1;
            }
            KeyCode::Delete if cursor < buffer.chars().count() => {
                let at = byte_at(&buffer, cursor);
                buffer.remove(at);
            }
            KeyCode::Up | KeyCode::Down => {
                // choice fields: cycle through the allowed values
                let key_path = self.fields.get(self.input_sel).map(|f| f.key);
                if let Some(list) = key_path.and_then(|k| self.deck.choices(k)) {
                    let n = list.len();
                    if n > 0 {
                        let cur = list.iter().position(|c| *c == buffer.trim());
                        let next = match (cur, key.code) {
                            (Some(i), KeyCode::Down) => (i + 1) % n,
                            (Some(i), _) => (i + n - 1) % n,
                            (None, _) => 0,
                        };
                        buffer = list.get(next).map(|c| c.to_string()).unwrap_or_default();
                        cursor = buffer.chars().count();
                    }
                }
            }
            KeyCode::Left => cursor = cursor.saturating_sub(1),
            KeyCode::Right => cursor = (cursor + 1).min(buffer.chars().count()),
            KeyCode::Home => cursor = 0,
            KeyCode::End => cursor = buffer.chars().count(),
            _ => {}
        }
        self.mode = Mode::Editing {
            buffer,
            cursor,
            error,
        };
        Vec::new()
    }

    fn commit_edit(&mut self, buffer: String) -> Vec<Command> {
        let Some(field) = self.fields.get(self.input_sel).copied() else {
            self.mode = Mode::Normal;
            return Vec::new();
        };
        if buffer.trim() == self.deck.value(field.key, self.display_units) {
            self.mode = Mode::Normal; // unchanged: no edit, no solve
            return Vec::new();
        }
        let mut next = self.deck.clone();
        match next.set_value(field.key, &buffer, self.display_units) {
            Ok(()) => {
                let before = self.replace_deck(next);
                self.undo.push((before, Some(field.key)));
                self.redo.clear();
                self.mode = Mode::Normal;
                let cmd = self.submit();
                self.dirty_keys.insert(field.key, self.generation);
                vec![cmd]
            }
            Err(e) => {
                let cursor = buffer.chars().count();
                self.mode = Mode::Editing {
                    buffer,
                    cursor,
                    error: Some(e),
                };
                Vec::new()
            }
        }
    }

    pub(super) fn undo_edit(&mut self) -> Vec<Command> {
        match self.undo.pop() {
            Some((deck, key)) => {
                let cur = self.replace_deck(deck);
                self.redo.push((cur, key));
                let cmd = self.submit();
                if let Some(k) = key {
                    self.dirty_keys.insert(k, self.generation);
                }
                self.message = Some(format!(
                    "undo{}",
                    key.map(|k| format!(" {k}")).unwrap_or_default()
                ));
                vec![cmd]
            }
            None => {
                self.message = Some("nothing to undo".into());
                Vec::new()
            }
        }
    }

    pub(super) fn redo_edit(&mut self) -> Vec<Command> {
        match self.redo.pop() {
            Some((deck, key)) => {
                let cur = self.replace_deck(deck);
                self.undo.push((cur, key));
                let cmd = self.submit();
                if let Some(k) = key {
                    self.dirty_keys.insert(k, self.generation);
                }
                self.message = Some(format!(
                    "redo{}",
                    key.map(|k| format!(" {k}")).unwrap_or_default()
                ));
                vec![cmd]
            }
            None => {
                self.message = Some("nothing to redo".into());
                Vec::new()
            }
        }
    }

    /// The first field from `start` on (cyclically) whose label or key contains `text`
    /// (case-insensitive).
    pub fn find_field(&self, text: &str, start: usize) -> Option<usize> {
        let t = text.to_lowercase();
        let n = self.fields.len();
        (0..n).map(|k| (start + k) % n.max(1)).find(|&i| {
            self.fields.get(i).is_some_and(|f| {
                f.label.to_lowercase().contains(&t) || f.key.to_lowercase().contains(&t)
            })
        })
    }

    pub(super) fn on_search_key(
        &mut self,
        key: KeyEvent,
        mut buffer: String,
        from: usize,
    ) -> Vec<Command> {
        match key.code {
            KeyCode::Esc => {
                self.input_sel = from;
                self.mode = Mode::Normal;
                return Vec::new();
            }
            KeyCode::Enter => {
                self.mode = Mode::Normal;
                return Vec::new();
            }
            // Tab: the next match after the one shown.
            KeyCode::Tab | KeyCode::Down => {
                if let Some(i) = self.find_field(&buffer, self.input_sel + 1) {
                    self.input_sel = i;
                }
            }
            KeyCode::Char(ch) if !key.modifiers.contains(KeyModifiers::CONTROL) => {
                buffer.push(ch);
                if let Some(i) = self.find_field(&buffer, from) {
                    self.input_sel = i;
                }
            }
            KeyCode::Backspace => {
                buffer.pop();
                self.input_sel = self.find_field(&buffer, from).unwrap_or(from);
            }
            _ => {}
        }
        self.mode = Mode::Search { buffer, from };
        Vec::new()
    }

    pub(super) fn on_prompt_key(
        &mut self,
        key: KeyEvent,
        kind: PromptKind,
        mut buffer: String,
    ) -> Vec<Command> {
        match key.code {
            KeyCode::Esc => {
                self.mode = Mode::Normal;
                self.quit_after_save = false;
                return Vec::new();
            }
            KeyCode::Enter => {
                self.mode = Mode::Normal;
                let path = PathBuf::from(buffer.trim());
                if buffer.trim().is_empty() {
                    return Vec::new();
                }
                return match kind {
                    // the deck's own file: a plain save (no question, like Ctrl-s)
                    PromptKind::SaveAs if self.path.as_ref() == Some(&path) => {
                        vec![Command::Save {
                            path,
                            deck: Box::new(self.deck.clone()),
                        }]
                    }
                    // another path: ask first if it exists (checked by the runtime)
                    PromptKind::SaveAs => vec![Command::CheckSaveTarget(path)],
                    PromptKind::Open => vec![Command::Open(path)],
                    PromptKind::Baseline => vec![Command::OpenBaseline(path)],
                    // ask first if it exists (checked by the runtime), as save-as does
                    PromptKind::Export(what) => vec![Command::CheckExportTarget { path, what }],
                };
            }
            KeyCode::Char(ch) if !key.modifiers.contains(KeyModifiers::CONTROL) => buffer.push(ch),
            KeyCode::Backspace => {
                buffer.pop();
            }
            _ => {}
        }
        self.mode = Mode::Prompt { kind, buffer };
        Vec::new()
    }
}
