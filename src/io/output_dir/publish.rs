//! Publishing an output set (the module docs of [`super`], "Publishing"): every target
//! checked first; the staged files renamed into place; the previous set's files this one
//! does not produce removed if still as recorded; the manifest and the state file
//! written, with the folder marked `INCOMPLETE` meanwhile. A set that cannot be published
//! is kept in a visible folder.

use super::{OutputDir, OutputError};
use crate::checksum::sha256_hex;
use crate::io::dir::{remove_tree, Dir};
use crate::io::set_state::{
    check_replaceable, is_recorded_output, is_recorded_place, Ours, OutputRecord, PlaceRecord,
    SetState,
};
use serde::{Deserialize, Serialize};
use std::collections::BTreeSet;

/// Name of the marker of a folder whose publishing was interrupted.
pub const INCOMPLETE_MARKER: &str = "INCOMPLETE";
/// First words of the marker (how gearwear recognises its own).
const MARKER_TEXT: &str = "gearwear was interrupted while publishing";
/// First words of the marker of a job that writes into the folder before it publishes
/// ([`OutputDir::mark_incomplete`]).
const WRITING_TEXT: &str = "gearwear is writing into this folder, or was interrupted";
/// Prefix of the folder that keeps a run's results when they could not be published.
pub const UNPUBLISHED_PREFIX: &str = "gearwear-unpublished-";

/// One published file.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct ManifestEntry {
    /// Path relative to the output folder, `/`-separated.
    pub path: String,
    /// SHA-256 of the content, lowercase hex.
    pub sha256: String,
    /// Size, bytes.
    pub bytes: u64,
}

/// What a published set holds (for people and scripts; gearwear acts on its state file).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Manifest {
    /// Name of the program that wrote the set ("gearwear").
    pub program: String,
    /// Version of the program.
    pub version: String,
    /// The command that wrote the set.
    pub command: String,
    /// Outputs of the run, with their checksums.
    pub files: Vec<ManifestEntry>,
    /// State files the run keeps for resuming (checkpoints, sweep cases), by name.
    #[serde(default)]
    pub state_files: Vec<String>,
}

fn is_marker(b: &[u8]) -> bool {
    b.starts_with(MARKER_TEXT.as_bytes()) || b.starts_with(WRITING_TEXT.as_bytes())
}

impl OutputDir {
    /// Mark the folder `INCOMPLETE` now, for a job that writes files into it before it
    /// publishes (a dataset's records and state files): the marker stays until this set
    /// is published, so a run killed half-way leaves the folder marked. Refused (and
    /// nothing written) when something other than gearwear's marker is at its name.
    pub fn mark_incomplete(&self) -> Result<(), OutputError> {
        check_replaceable(&self.root, INCOMPLETE_MARKER, Ours::Format(None, is_marker))?;
        let text = format!(
            "{WRITING_TEXT} (`gearwear {}`): the files here may be unfinished until it publishes its results. If no gearwear runs here, run the command again.\n",
            self.command
        );
        self.root
            .write_new(&self.staging, INCOMPLETE_MARKER, text.as_bytes())
            .map(|_| ())
    }

    /// Publish the staged files as the folder's new set; returns its manifest.
    pub fn publish(mut self) -> Result<Manifest, OutputError> {
        // 1. Every target must be free, or gearwear's own as recorded.
        let (targets, mut conflicts) = self.publish_targets();
        if !conflicts.is_empty() {
            conflicts.sort();
            conflicts.dedup();
            return Err(self.keep_unpublished(conflicts));
        }
        // 2. Mark, move into place, rename the logs.
        let marker = format!(
            "{MARKER_TEXT} its results into this folder (`gearwear {}`): the files here may belong to different runs. Run the command again.\n",
            self.command
        );
        let marker_entry =
            self.root
                .write_new(&self.staging, INCOMPLETE_MARKER, marker.as_bytes())?;
        let mut st = SetState::new(self.root.entry_self()?.inode, &self.command);
        let files = self.move_into_place(&targets, &mut st)?;
        // 3. The previous set's files this one does not produce, if still as recorded.
        self.remove_previous()?;
        // 4. The manifest, the state, then the marker goes.
        let manifest = self.write_manifest(files, &mut st)?;
        self.write_state_file(&st)?;
        if matches!(self.root.entry(INCOMPLETE_MARKER)?, Some(e) if e.inode == marker_entry.inode) {
            self.root.remove_file(INCOMPLETE_MARKER)?;
        }
        self.root.sync()?;
        self.published = true;
        let _ = remove_tree(&self.root, &self.staging_name);
        Ok(manifest)
    }

    /// Where each staged file goes (relative path, folder, name), and why any target,
    /// log, manifest or marker cannot be replaced (not free, and not gearwear's own as
    /// recorded).
    fn publish_targets(&self) -> (Vec<(String, Dir, String)>, Vec<String>) {
        let mut conflicts = Vec::new();
        let mut targets = Vec::new();
        for rel in self.staged.keys() {
            let checked = self.root.descend(rel, true).and_then(|(dir, name)| {
                check_replaceable(&dir, &name, Ours::Recorded(self.previous.output(rel)))?;
                Ok((dir, name))
            });
            match checked {
                Ok((dir, name)) => targets.push((rel.clone(), dir, name)),
                Err(e) => conflicts.push(e.to_string()),
            }
        }
        for (_, to, recognise) in &self.at_publish {
            let ours = Ours::Format(self.previous.state_file(to), *recognise);
            let checked = self
                .root
                .descend(to, true)
                .and_then(|(dir, name)| check_replaceable(&dir, &name, ours));
            if let Err(e) = checked {
                conflicts.push(e.to_string());
            }
        }
        for (name, ours) in [
            (
                self.manifest_name.as_str(),
                Ours::Recorded(self.previous.output(&self.manifest_name)),
            ),
            (INCOMPLETE_MARKER, Ours::Format(None, is_marker)),
        ] {
            if let Err(e) = check_replaceable(&self.root, name, ours) {
                conflicts.push(e.to_string());
            }
        }
        (targets, conflicts)
    }

    /// Move the staged files to their `targets` and the logs to their names, recording
    /// every output and state file in `st`; the manifest's entries.
    fn move_into_place(
        &mut self,
        targets: &[(String, Dir, String)],
        st: &mut SetState,
    ) -> Result<Vec<ManifestEntry>, OutputError> {
        let mut files = Vec::with_capacity(targets.len() + 1);
        for (rel, dir, name) in targets {
            let (sdir, sname) = self.staging.descend(rel, false)?;
            sdir.rename_to(&sname, dir, name)?;
            let s = &self.staged[rel];
            st.outputs.push(OutputRecord {
                path: rel.clone(),
                inode: s.entry.inode,
                bytes: s.bytes,
                sha256: s.sha256.clone(),
            });
            files.push(ManifestEntry {
                path: rel.clone(),
                sha256: s.sha256.clone(),
                bytes: s.bytes,
            });
        }
        for (from, to, _) in std::mem::take(&mut self.at_publish) {
            let (fdir, fname) = self.root.descend(&from, false)?;
            let (tdir, tname) = self.root.descend(&to, true)?;
            if fdir.entry(&fname)?.is_some() {
                fdir.rename_to(&fname, &tdir, &tname)?;
            }
            self.state.insert(to);
        }
        for rel in &self.state {
            if let Ok((dir, name)) = self.root.descend(rel, false) {
                if let Some(e) = dir.entry(&name)? {
                    st.state_files.push(PlaceRecord {
                        path: rel.clone(),
                        inode: e.inode,
                    });
                }
            }
        }
        Ok(files)
    }

    /// Remove the previous set's outputs and state files this set does not produce, each
    /// only if it is still the file recorded.
    fn remove_previous(&self) -> Result<(), OutputError> {
        let now: BTreeSet<&str> = self
            .staged
            .keys()
            .chain(self.state.iter())
            .map(String::as_str)
            .collect();
        for rec in &self.previous.outputs {
            if now.contains(rec.path.as_str()) || rec.path == self.manifest_name {
                continue;
            }
            if let Ok((dir, name)) = self.root.descend(&rec.path, false) {
                if is_recorded_output(&dir, &name, rec)? {
                    dir.remove_file(&name)?;
                }
            }
        }
        for rec in &self.previous.state_files {
            if now.contains(rec.path.as_str()) {
                continue;
            }
            if let Ok((dir, name)) = self.root.descend(&rec.path, false) {
                if is_recorded_place(&dir, &name, rec)? {
                    dir.remove_file(&name)?;
                }
            }
        }
        Ok(())
    }

    /// Write the set's manifest of `files` (recorded in `st` as an output too).
    fn write_manifest(
        &self,
        files: Vec<ManifestEntry>,
        st: &mut SetState,
    ) -> Result<Manifest, OutputError> {
        let manifest = Manifest {
            program: "gearwear".into(),
            version: env!("CARGO_PKG_VERSION").into(),
            command: self.command.clone(),
            files,
            state_files: self.state.iter().cloned().collect(),
        };
        let text = serde_json::to_string_pretty(&manifest).map_err(|e| {
            OutputError::new(
                "write",
                &self.root.join(&self.manifest_name),
                e.to_string(),
                None,
            )
        })?;
        let me = self
            .root
            .write_new(&self.staging, &self.manifest_name, text.as_bytes())?;
        st.outputs.push(OutputRecord {
            path: self.manifest_name.clone(),
            inode: me.inode,
            bytes: text.len() as u64,
            sha256: sha256_hex(text.as_bytes()),
        });
        Ok(manifest)
    }

    /// Keep the staged results in a visible folder when they cannot be published; the
    /// error says why and where they are.
    fn keep_unpublished(&mut self, conflicts: Vec<String>) -> OutputError {
        let kept = format!(
            "{UNPUBLISHED_PREFIX}{}-{}",
            self.command,
            std::process::id()
        );
        let where_ = match self.root.entry(&kept) {
            Ok(None) => match self.root.rename_to(&self.staging_name, &self.root, &kept) {
                Ok(()) => {
                    self.published = true;
                    let mut st = self.previous.clone();
                    st.staging.clear();
                    let _ = self.write_state_file(&st);
                    format!(
                        "this run's results are kept in {}",
                        self.root.join(&kept).display()
                    )
                }
                Err(_) => "this run's results could not be kept".into(),
            },
            _ => "this run's results could not be kept".into(),
        };
        OutputError::new(
            "publish into",
            self.root.path(),
            format!(
                "this run's files cannot all be put in place ({} problem(s)): {}; nothing was replaced, and {where_}",
                conflicts.len(),
                conflicts.join("; ")
            ),
            None,
        )
    }
}
