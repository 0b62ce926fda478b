//! `ergocell trajectories`: the safety engineer's review workflow for the class handover trajectories.
//!
//! ```text
//! ergocell trajectories validate [--class c2] [--json]   plan + check, print the report; non-zero on rejection
//! ergocell trajectories design --out-dir designed/       choose each class's handover point for the
//!                                                        people it serves; write class files to review
//! ergocell trajectories lock [--class c2]                write trajectories/locks/<class>.lock.toml
//! ergocell trajectories approve --class c2 --by <principal> --key ~/.ssh/id_ed25519
//!                                                        sign off the lock's hash (SSH signature) in
//!                                                        trajectories/approvals/<class>.toml
//! ergocell trajectories approve --class c2 --by <principal> --message-out approval.txt
//!   ssh-keygen -Y sign -f ~/.ssh/id_ed25519 -n ergocell-trajectory-approval approval.txt
//! ergocell trajectories approve --class c2 --signed approval.txt   (reads approval.txt.sig)
//!                                                        the same with a passphrase, an agent or a
//!                                                        hardware key: ssh-keygen signs
//! ergocell trajectories approval-message --class c2 --entry 0
//!                                                        print what entry 0 signed, for
//!                                                        `ssh-keygen -Y verify`
//! ergocell trajectories verify [--class c2] [--allow-unapproved]
//!                                                        lock hash, input hashes, limits, approvals agree,
//!                                                        and the lock holds what validation produces now
//! ergocell trajectories sign-approvers --key <site authority key>
//! ergocell trajectories sign-approvers --signed approvers.sig
//!                                                        the site's approvers authority signs
//!                                                        config/approvers/ (approvers.sig)
//! ergocell trajectories approvers-message               what that signature covers, for ssh-keygen
//! ```
//!
//! The keys in `config/approvers/allowed_signers` count only under the signature of the site's
//! approvers authority, whose public key is installed read-only outside the project
//! ([`ergocell::trust_anchor`]): editing the project folder can stop the cell, never approve.
//!
//! Paths default to `trajectories/` and `config/cell.toml` under the current directory. The lock is a
//! software guarantee on top of the robot's own safety controller, not a replacement for it.

use std::fs;
use std::path::{Path, PathBuf};

use anyhow::{bail, Context as _};
use ergocell::trust_anchor;
use ergocell_robot::authority;
use ergocell_robot::lock::{self, ApprovalsFile, LockFile, VerifyInputs};
use ergocell_robot::signing::{self, printable, TrustedSigners};
use ergocell_robot::{
    plan_and_validate, CellConfig, InputHashes, PlanInputs, RobotModel, TrajectoryClass,
    TrajectoryLayout, TrajectorySpec, TrustFiles,
};

use super::UsageError;

mod design;

/// Arguments of `ergocell trajectories`.
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(subcommand)]
    pub command: Sub,
    /// Directory of the trajectory files (`c1.toml`…); locks go to `<dir>/locks`, approvals to `<dir>/approvals`.
    #[arg(long, global = true, default_value = TrajectoryLayout::DEFAULT_DIR)]
    pub trajectories_dir: PathBuf,
    /// Cell configuration (its `[robot]`, `[station]` and `[monitor]` tables; the URDF path is relative to this file).
    #[arg(long, global = true, default_value = "config/cell.toml")]
    pub cell: PathBuf,
}

#[derive(Debug, clap::Subcommand)]
pub enum Sub {
    /// Plan and validate (IK + QP + checks) and print the report; exits non-zero on any rejection.
    Validate {
        /// Only this class (c1, c2, c3); default all.
        #[arg(long, value_parser = parse_class)]
        class: Option<TrajectoryClass>,
        /// Print the reports as JSON (SI units) instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Choose each class's handover point for the people it serves (ANSUR II's fitting half,
    /// the twin's body model, the posture cost) among the points `validate` accepts, and write the
    /// class files, `design.json` and `design_cost.svg` to a new folder for review. Locks and
    /// approvals follow as for any edited class file.
    Design {
        /// Where to write; existing files are never overwritten.
        #[arg(long)]
        out_dir: PathBuf,
        /// Spacing of the candidate points in the class's grasp band, metres.
        #[arg(long, default_value_t = 0.01)]
        step: f64,
        /// At most this many fitting people per class, evenly spread over the subject ids.
        #[arg(long, default_value_t = 150)]
        people: usize,
        /// The unadapted cell's one handover point (station frame: forward,lateral,height,
        /// metres), which c1's and c3's points must improve on: the same default as the twin's
        /// `sim adaptation --before-handover`.
        #[arg(
            long,
            value_parser = crate::commands::sim::parse_point,
            default_value = crate::commands::sim::BEFORE_HANDOVER
        )]
        before_handover: [f64; 3],
    },
    /// Validate and write the lock file of each accepted class.
    Lock {
        #[arg(long, value_parser = parse_class)]
        class: Option<TrajectoryClass>,
    },
    /// Record a safety engineer's signed sign-off of the current lock's hash (after an integrity
    /// check): with `--key`, or in two steps with `--message-out` and then `--signed`.
    Approve {
        #[arg(long, value_parser = parse_class)]
        class: TrajectoryClass,
        #[command(flatten)]
        signing: Signing,
    },
    /// Withdraw the standing approval of a class (any trusted approver may): its lock does not run
    /// again until a safety engineer approves it anew. With `--key`, or in two steps with
    /// `--message-out` and then `--signed`, like `approve`.
    Withdraw {
        #[arg(long, value_parser = parse_class)]
        class: TrajectoryClass,
        #[command(flatten)]
        signing: Signing,
    },
    /// Print the exact message an approval entry signed (for `ssh-keygen -Y verify`), and with
    /// `--signature-out` write its signature to a new file. Write the message to a file first and
    /// then run ssh-keygen: in one pipeline ssh-keygen may open the signature before it exists.
    ApprovalMessage {
        #[arg(long, value_parser = parse_class)]
        class: TrajectoryClass,
        /// 0-based entry in trajectories/approvals/<class>.toml.
        #[arg(long)]
        entry: usize,
        /// Also write the entry's armored signature to this new file.
        #[arg(long)]
        signature_out: Option<PathBuf>,
    },
    /// Check that lock files, input hashes, limits and approvals agree; exits non-zero on any problem.
    Verify {
        #[arg(long, value_parser = parse_class)]
        class: Option<TrajectoryClass>,
        /// Check integrity only and report missing approvals without failing (CI before sign-off).
        #[arg(long)]
        allow_unapproved: bool,
    },
    /// The site's approvers authority signs the approvers' files (allowed_signers and revoked_keys
    /// beside the cell file) into approvers/approvers.sig: with `--key`, or `--signed` with a
    /// signature `ssh-keygen -Y sign -n ergocell-approvers` made over `approvers-message`.
    SignApprovers {
        /// The authority's OpenSSH Ed25519 private key (not passphrase-protected).
        #[arg(long, conflicts_with = "signed", required_unless_present = "signed")]
        key: Option<PathBuf>,
        /// A signature made by `ssh-keygen` over the output of `approvers-message`.
        #[arg(long)]
        signed: Option<PathBuf>,
    },
    /// Print the exact message the authority's signature over the approvers' files covers.
    ApproversMessage,
}

/// How `approve` and `withdraw` are signed: here with a key file, or in two steps through
/// `ssh-keygen`.
#[derive(Debug, clap::Args)]
pub struct Signing {
    /// The signer's principal, exactly as config/approvers/allowed_signers lists it (with `--key`
    /// or `--message-out`).
    #[arg(long, required_unless_present = "signed")]
    by: Option<String>,
    /// Sign with this OpenSSH Ed25519 private key (not passphrase-protected; for one that is, or an
    /// agent or hardware key, use `--message-out` and `ssh-keygen -Y sign`).
    #[arg(long, conflicts_with_all = ["message_out", "signed"])]
    key: Option<PathBuf>,
    /// Write the message to sign to this new file (never overwritten) and stop: sign it with
    /// `ssh-keygen -Y sign -f <key> -n ergocell-trajectory-approval <file>`, then `--signed <file>`.
    #[arg(long, conflicts_with = "signed")]
    message_out: Option<PathBuf>,
    /// Append the entry of this message file, signed by `ssh-keygen` into `<file>.sig`.
    #[arg(long, conflicts_with = "by")]
    signed: Option<PathBuf>,
    /// The signature file for `--signed` (default `<message>.sig`).
    #[arg(long, requires = "signed")]
    signature: Option<PathBuf>,
}

fn parse_class(s: &str) -> Result<TrajectoryClass, String> {
    s.parse()
        .map_err(|e: ergocell_robot::RobotError| e.to_string())
}

pub fn run(args: &Args) -> anyhow::Result<()> {
    let ctx = Context::load(args)?;
    match &args.command {
        Sub::Validate { class, json } => validate(&ctx, *class, *json),
        Sub::Lock { class } => lock_classes(&ctx, *class),
        Sub::Design {
            out_dir,
            step,
            people,
            before_handover,
        } => design::design(&ctx, out_dir, *step, *people, *before_handover),
        Sub::Approve { class, signing } => approve(
            &ctx,
            *class,
            signing.by.as_deref(),
            ApproveHow::from_args(signing)?,
        ),
        Sub::Withdraw { class, signing } => withdraw(
            &ctx,
            *class,
            signing.by.as_deref(),
            ApproveHow::from_args(signing)?,
        ),
        Sub::ApprovalMessage {
            class,
            entry,
            signature_out,
        } => approval_message(&ctx, *class, *entry, signature_out.as_deref()),
        Sub::Verify {
            class,
            allow_unapproved,
        } => verify(&ctx, *class, *allow_unapproved),
        Sub::SignApprovers { key, signed } => {
            sign_approvers(&ctx, key.as_deref(), signed.as_deref())
        }
        Sub::ApproversMessage => {
            print!(
                "{}",
                authority::approvers_message(&ctx.trust_texts.0, &ctx.trust_texts.1)
            );
            Ok(())
        }
    }
}

/// The cell, the robot and the paths, read once.
struct Context {
    layout: TrajectoryLayout,
    cell: CellConfig,
    urdf_text: String,
    model: RobotModel,
    /// The folder of the cell file (the approvers' files are in its `approvers/`).
    cell_dir: PathBuf,
    /// The trusted approvers' files' texts (allowed signers, revoked keys).
    trust_texts: (String, String),
    /// The approvers trusted under the site's authority; none when they are not (`trust_problem`).
    trusted: TrustedSigners,
    /// Why the approvers' files are not trusted, when they are not.
    trust_problem: Option<String>,
}

impl Context {
    fn load(args: &Args) -> anyhow::Result<Self> {
        let cell_text = read(&args.cell)?;
        let cell = CellConfig::from_toml_str(&cell_text)
            .map_err(|e| UsageError(format!("{}: {e}", args.cell.display())))?;
        let urdf_path = args
            .cell
            .parent()
            .unwrap_or_else(|| Path::new("."))
            .join(&cell.robot.urdf);
        let urdf_text = read(&urdf_path)?;
        let model =
            RobotModel::from_urdf_str(&urdf_text, &cell.robot.base_link, &cell.robot.flange_link)
                .map_err(|e| UsageError(format!("{}: {e}", urdf_path.display())))?;
        let dir = args.cell.parent().unwrap_or_else(|| Path::new("."));
        let allowed_path = dir.join(signing::ALLOWED_SIGNERS);
        let revoked_path = dir.join(signing::REVOKED_KEYS);
        let allowed = read(&allowed_path)?;
        let revoked = read(&revoked_path)?;
        TrustedSigners::parse(&allowed, &revoked).map_err(|e| {
            UsageError(format!(
                "{} / {}: {e}",
                allowed_path.display(),
                revoked_path.display()
            ))
        })?;
        let anchored =
            trust_anchor::trusted_signers(dir, &allowed, &revoked, &trust_anchor::anchor_dir());
        let (trusted, trust_problem) = match anchored {
            Ok(t) => (t, None),
            Err(why) => (TrustedSigners::default(), Some(why.to_string())),
        };
        Ok(Self {
            layout: TrajectoryLayout::new(&args.trajectories_dir),
            cell,
            urdf_text,
            model,
            cell_dir: dir.to_owned(),
            trust_texts: (allowed, revoked),
            trusted,
            trust_problem,
        })
    }

    /// The class's parsed trajectory file and the current input hashes.
    fn spec(&self, class: TrajectoryClass) -> anyhow::Result<(TrajectorySpec, InputHashes)> {
        let (spec, hashes, _) = self.spec_with_text(class)?;
        Ok((spec, hashes))
    }

    /// [`Context::spec`] and the file's text, read once.
    fn spec_with_text(
        &self,
        class: TrajectoryClass,
    ) -> anyhow::Result<(TrajectorySpec, InputHashes, String)> {
        let path = self.layout.spec(class);
        let text = read(&path)?;
        let spec = TrajectorySpec::from_toml_str(&text)
            .map_err(|e| UsageError(format!("{}: {e}", path.display())))?;
        if spec.class != class {
            return Err(UsageError(format!(
                "{}: file declares class {}, expected {class}",
                path.display(),
                spec.class
            ))
            .into());
        }
        let hashes = InputHashes::new(
            text.as_bytes(),
            self.urdf_text.as_bytes(),
            &self.cell,
            TrustFiles {
                allowed_signers: self.trust_texts.0.as_bytes(),
                revoked_keys: self.trust_texts.1.as_bytes(),
            },
            env!("CARGO_PKG_VERSION"),
        );
        Ok((spec, hashes, text))
    }
}

/// Reads a file of the cell or the trajectories folder. `trajectories` works on the files on disk
/// only (it writes locks and approvals beside them), so a missing default says where it looked.
fn read(path: &Path) -> anyhow::Result<String> {
    ergocell::input::read_text(path, ergocell::input::Kind::Config).with_context(|| {
        if path.is_relative() {
            format!(
                "cannot read {} (relative to {}: run from the cell's folder, or pass --cell and --trajectories-dir)",
                path.display(),
                ergocell::shipped::working_dir()
            )
        } else {
            format!("cannot read {}", path.display())
        }
    })
}

fn classes(class: Option<TrajectoryClass>) -> Vec<TrajectoryClass> {
    class.map_or_else(|| TrajectoryClass::ALL.to_vec(), |c| vec![c])
}

fn validate(ctx: &Context, class: Option<TrajectoryClass>, json: bool) -> anyhow::Result<()> {
    let mut failed = Vec::new();
    let mut json_out = Vec::new();
    for class in classes(class) {
        let (spec, hashes) = ctx.spec(class)?;
        let inputs = PlanInputs {
            model: &ctx.model,
            cell: &ctx.cell,
            spec: &spec,
            hashes: &hashes,
        };
        match plan_and_validate(&inputs) {
            Ok(v) => {
                if !v.report.accepted {
                    failed.push(class);
                }
                if json {
                    json_out.push(serde_json::json!({ "class": class, "report": v.report }));
                } else {
                    println!("{}", v.report);
                }
            }
            Err(e) => {
                failed.push(class);
                if json {
                    json_out.push(serde_json::json!({ "class": class, "error": e.to_string() }));
                } else {
                    println!("Trajectory validation — class {class} — REJECTED\n  {e}\n");
                }
            }
        }
    }
    if json {
        println!("{}", serde_json::to_string_pretty(&json_out)?);
    }
    if failed.is_empty() {
        Ok(())
    } else {
        bail!("rejected: {}", list(&failed))
    }
}

/// Validates every class asked for first and writes their locks only when all are accepted: a bad
/// class (or an unreadable trajectory file) leaves every lock as it was, never some re-locked and
/// some not.
fn lock_classes(ctx: &Context, class: Option<TrajectoryClass>) -> anyhow::Result<()> {
    let mut failed = Vec::new();
    let mut bad_input = false;
    let mut locks = Vec::new();
    for class in classes(class) {
        let locked = ctx.spec(class).and_then(|(spec, hashes)| {
            let inputs = PlanInputs {
                model: &ctx.model,
                cell: &ctx.cell,
                spec: &spec,
                hashes: &hashes,
            };
            plan_and_validate(&inputs)
                .and_then(ergocell_robot::Validation::into_locked)
                .map_err(anyhow::Error::from)
        });
        match locked {
            Ok(l) => locks.push((class, LockFile::from_locked(&l))),
            Err(e) => {
                eprintln!("{class}: not locked: {e:#}");
                bad_input |= e.chain().any(<dyn std::error::Error>::is::<UsageError>);
                failed.push(class);
            }
        }
    }
    if !failed.is_empty() {
        let why = format!(
            "not locked: {} — no lock file was written (every lock is as it was)",
            list(&failed)
        );
        // A malformed file is bad input (exit 2); a class that does not validate is a rejection (1).
        return Err(if bad_input {
            UsageError(why).into()
        } else {
            anyhow::anyhow!(why)
        });
    }
    for (class, lock) in locks {
        let path = ctx.layout.lock(class);
        write(&path, &lock.to_toml()?)?;
        println!(
            "{class}: locked {} (lock_sha256 {})",
            path.display(),
            lock.lock_sha256
        );
        println!("    review it, then: ergocell trajectories approve --class {class} --by <principal> --key <ssh key>");
    }
    if let Some(why) = &ctx.trust_problem {
        eprintln!("note: the approvers' files are not trusted, so no approval of these locks will count until they are: {why}");
    }
    Ok(())
}

/// Re-plan the class from the current inputs and check that the lock holds exactly that trajectory:
/// a lock edited by hand (and re-hashed) is refused even though its hashes agree.
fn matches_validation(
    ctx: &Context,
    spec: &TrajectorySpec,
    current: &InputHashes,
    lock: &LockFile,
) -> Result<(), String> {
    let inputs = PlanInputs {
        model: &ctx.model,
        cell: &ctx.cell,
        spec,
        hashes: current,
    };
    let validated = plan_and_validate(&inputs)
        .and_then(ergocell_robot::Validation::into_locked)
        .map_err(|e| format!("validation of the current inputs fails: {e}"))?;
    lock::check_matches_validation(lock, &validated).map_err(|e| e.to_string())
}

/// How `approve` gets its signature.
enum ApproveHow<'a> {
    /// Sign here with this private key file.
    Key(&'a Path),
    /// Write the message to sign and stop.
    MessageOut(&'a Path),
    /// Append the message signed by `ssh-keygen`.
    Signed {
        message: &'a Path,
        signature: PathBuf,
    },
}

impl<'a> ApproveHow<'a> {
    /// The one way `approve` or `withdraw` was asked to sign.
    fn from_args(signing: &'a Signing) -> Result<Self, UsageError> {
        match (&signing.key, &signing.message_out, &signing.signed) {
            (Some(key), None, None) => Ok(ApproveHow::Key(key)),
            (None, Some(out), None) => Ok(ApproveHow::MessageOut(out)),
            (None, None, Some(message)) => Ok(ApproveHow::Signed {
                message,
                signature: signing
                    .signature
                    .clone()
                    .unwrap_or_else(|| with_suffix(message, ".sig")),
            }),
            _ => Err(UsageError(
                "needs one of --key <private key>, --message-out <file> or --signed <file>"
                    .to_owned(),
            )),
        }
    }
}

/// The approvals folder's lock: held by `approve` and `withdraw` from reading the approvals file to
/// recording in the witness, so two engineers approving at once both land, one after the other
/// (each reads what the other wrote). A second command waits, and says it waits.
struct ApprovalsLock {
    _file: fs::File,
}

/// The lock file's name in the approvals folder.
const APPROVALS_LOCK: &str = ".approvals.lock";

impl ApprovalsLock {
    /// The lock for a command that writes the approvals file; none for `--message-out`, which
    /// only writes the message to sign.
    fn for_writing(
        ctx: &Context,
        class: TrajectoryClass,
        how: &ApproveHow<'_>,
    ) -> anyhow::Result<Option<Self>> {
        match how {
            ApproveHow::MessageOut(_) => Ok(None),
            _ => Self::take(ctx, class).map(Some),
        }
    }

    fn take(ctx: &Context, class: TrajectoryClass) -> anyhow::Result<Self> {
        let path = ctx.layout.approvals(class);
        let dir = path.parent().unwrap_or_else(|| Path::new("."));
        fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
        let lock_path = dir.join(APPROVALS_LOCK);
        let file = fs::OpenOptions::new()
            .create(true)
            .truncate(false)
            .write(true)
            .open(&lock_path)
            .with_context(|| format!("cannot open the lock {}", lock_path.display()))?;
        match file.try_lock() {
            Ok(()) => {}
            Err(fs::TryLockError::WouldBlock) => {
                eprintln!(
                    "waiting: another approve or withdraw holds {} (it is writing the approvals)",
                    lock_path.display()
                );
                file.lock()
                    .with_context(|| format!("cannot lock {}", lock_path.display()))?;
            }
            Err(fs::TryLockError::Error(e)) => {
                return Err(e).with_context(|| format!("cannot lock {}", lock_path.display()))
            }
        }
        // Holding the lock, no other command is writing: a temporary file left beside the approvals
        // is one a killed command left behind.
        remove_stale_partials(dir);
        Ok(Self { _file: file })
    }
}

/// Removes the temporary files of approvals writes that never finished (`.<name>.partial-<pid>`,
/// left by a command killed mid-write), saying each.
fn remove_stale_partials(dir: &Path) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let name = name.to_string_lossy();
        if name.starts_with('.') && name.contains(".partial-") {
            match fs::remove_file(entry.path()) {
                Ok(()) => eprintln!(
                    "note: removed {}, left by an approve or withdraw that was stopped mid-write",
                    entry.path().display()
                ),
                Err(e) => eprintln!(
                    "note: {} is left by a write that was stopped; cannot remove it: {e}",
                    entry.path().display()
                ),
            }
        }
    }
}

/// Refuses an entry whose time `verify` would refuse, before it is written (it would otherwise be
/// announced as recorded and then block the class until withdrawn).
fn check_entry_time(at_utc: &str, what: &str) -> anyhow::Result<()> {
    signing::check_approval_time(at_utc, trust_anchor::now_unix())
        .map_err(|e| anyhow::anyhow!("{e}\nrefusing to {what}: nothing was written"))
}

/// The class's approvals file (empty if there is none yet), its chain checked and checked against
/// the cell's witness ([`ergocell::witness`]): a file cut back is refused before anything is added.
fn load_approvals(ctx: &Context, class: TrajectoryClass) -> anyhow::Result<ApprovalsFile> {
    let path = ctx.layout.approvals(class);
    let file = if path.exists() {
        ApprovalsFile::from_toml_str(&read(&path)?)
            .and_then(|f| f.check_chain().map(|()| f))
            .map_err(|e| UsageError(format!("{}: {e}", path.display())))?
    } else {
        // A missing file is an empty chain: one the witness saw entries of was deleted.
        ApprovalsFile::default()
    };
    witness(ctx, &path, class, &file)?;
    Ok(file)
}

/// The witness's notes on standard error.
fn print_notes(notes: Vec<ergocell::witness::WitnessNote>) {
    for note in notes {
        eprintln!("note: {note}");
    }
}

/// [`ergocell::witness::observe`] for the commands that write the approvals file: a refusal names
/// the file.
fn witness(
    ctx: &Context,
    path: &Path,
    class: TrajectoryClass,
    file: &ApprovalsFile,
) -> anyhow::Result<()> {
    ergocell::witness::observe(path, class, file, &ctx.trusted, trust_anchor::now_unix())
        .map(print_notes)
        .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))
}

/// The two-step flow's first step: `message` written to the new file `out`, and what to do next.
fn message_written(
    class: TrajectoryClass,
    out: &Path,
    message: &str,
    what: &str,
    command: &str,
) -> anyhow::Result<()> {
    write_new(out, message)?;
    println!(
        "{class}: wrote the {what} message to {} — sign it with\n  ssh-keygen -Y sign -f <your key> -n {} {}\nthen: ergocell trajectories {command} --class {class} --signed {}",
        out.display(),
        signing::APPROVAL_NAMESPACE,
        out.display(),
        out.display()
    );
    Ok(())
}

fn with_suffix(path: &Path, suffix: &str) -> PathBuf {
    let mut s = path.as_os_str().to_owned();
    s.push(suffix);
    PathBuf::from(s)
}

fn approve(
    ctx: &Context,
    class: TrajectoryClass,
    by: Option<&str>,
    how: ApproveHow<'_>,
) -> anyhow::Result<()> {
    if let Some(why) = &ctx.trust_problem {
        bail!("the approvers' files are not trusted: {why}\nrefusing to approve");
    }
    let (spec, current) = ctx.spec(class)?;
    let lock_path = ctx.layout.lock(class);
    let lock_text = read(&lock_path)
        .with_context(|| format!("run `ergocell trajectories lock --class {class}` first"))?;
    let inputs = VerifyInputs {
        class,
        lock_toml: &lock_text,
        current_inputs: &current,
        model: &ctx.model,
        approvals_toml: None,
        trusted: &ctx.trusted,
    };
    let lock =
        lock::verify_integrity(&inputs).map_err(|f| anyhow::anyhow!("{f}\nrefusing to approve"))?;
    matches_validation(ctx, &spec, &current, &lock)
        .map_err(|e| anyhow::anyhow!("{e}\nrefusing to approve"))?;
    let approvals_path = ctx.layout.approvals(class);
    let _lock = ApprovalsLock::for_writing(ctx, class, &how)?;
    let mut file = load_approvals(ctx, class)?;
    let approval = match how {
        ApproveHow::Key(key_path) => {
            let by = by.unwrap_or_default();
            let key = signing::private_key_from_openssh(&read(key_path)?)
                .map_err(|e| UsageError(format!("{}: {e}", key_path.display())))?;
            file.approve(&lock, by, &now_rfc3339()?, &ctx.trusted, &key)
                .map_err(|e| anyhow::anyhow!("{e}\nrefusing to approve"))?
                .clone()
        }
        ApproveHow::MessageOut(out) => {
            let message = file.next_message(&lock, by.unwrap_or_default(), &now_rfc3339()?)?;
            return message_written(class, out, &message, "approval", "approve");
        }
        ApproveHow::Signed { message, signature } => {
            let text = read(message)?;
            let sig = read(&signature)?;
            file.append_signed(&lock, &text, &sig, &ctx.trusted)
                .map_err(|e| anyhow::anyhow!("{e}\nrefusing to approve"))?
                .clone()
        }
    };
    check_entry_time(&approval.approved_at_utc, "approve")?;
    write(&approvals_path, &file.to_toml()?)?;
    witness(ctx, &approvals_path, class, &file)?;
    println!(
        "{class}: approved by {} at {} (signature verified) — lock_sha256 {} — recorded in {}",
        printable(&approval.approved_by),
        approval.approved_at_utc,
        approval.lock_sha256,
        approvals_path.display()
    );
    Ok(())
}

fn withdraw(
    ctx: &Context,
    class: TrajectoryClass,
    by: Option<&str>,
    how: ApproveHow<'_>,
) -> anyhow::Result<()> {
    if let Some(why) = &ctx.trust_problem {
        bail!("the approvers' files are not trusted: {why}\nrefusing to withdraw");
    }
    let approvals_path = ctx.layout.approvals(class);
    if !approvals_path.exists() {
        return Err(UsageError(format!(
            "{} does not exist: {class} has no approval to withdraw",
            approvals_path.display()
        ))
        .into());
    }
    let _lock = ApprovalsLock::for_writing(ctx, class, &how)?;
    let mut file = load_approvals(ctx, class)?;
    let entry = match how {
        ApproveHow::Key(key_path) => {
            let key = signing::private_key_from_openssh(&read(key_path)?)
                .map_err(|e| UsageError(format!("{}: {e}", key_path.display())))?;
            file.withdraw(
                class,
                by.unwrap_or_default(),
                &now_rfc3339()?,
                &ctx.trusted,
                &key,
            )
            .map_err(|e| anyhow::anyhow!("{e}\nrefusing to withdraw"))?
            .clone()
        }
        ApproveHow::MessageOut(out) => {
            let message =
                file.next_withdrawal_message(class, by.unwrap_or_default(), &now_rfc3339()?)?;
            return message_written(class, out, &message, "withdrawal", "withdraw");
        }
        ApproveHow::Signed { message, signature } => {
            let text = read(message)?;
            let sig = read(&signature)?;
            file.append_signed_withdrawal(class, &text, &sig, &ctx.trusted)
                .map_err(|e| anyhow::anyhow!("{e}\nrefusing to withdraw"))?
                .clone()
        }
    };
    check_entry_time(&entry.approved_at_utc, "withdraw")?;
    write(&approvals_path, &file.to_toml()?)?;
    witness(ctx, &approvals_path, class, &file)?;
    println!(
        "{class}: approval of lock_sha256 {} WITHDRAWN by {} at {} (signature verified) — recorded in {}; \
         the lock does not run until it is approved again",
        entry.lock_sha256,
        printable(&entry.approved_by),
        entry.approved_at_utc,
        approvals_path.display()
    );
    Ok(())
}

fn approval_message(
    ctx: &Context,
    class: TrajectoryClass,
    entry: usize,
    signature_out: Option<&Path>,
) -> anyhow::Result<()> {
    let path = ctx.layout.approvals(class);
    let file = ApprovalsFile::from_toml_str(&read(&path)?)
        .map_err(|e| UsageError(format!("{}: {e}", path.display())))?;
    let Some(a) = file.approval.get(entry) else {
        return Err(UsageError(format!(
            "{} has {} entries; there is no entry {entry}",
            path.display(),
            file.approval.len()
        ))
        .into());
    };
    // Only well-formed fields are shown (they come from a file anyone may have edited).
    signing::check_claim(&a.claim())
        .map_err(|e| UsageError(format!("{} entry {entry}: {e}", path.display())))?;
    if let Some(out) = signature_out {
        write_new(out, &a.signature)?;
    }
    print!("{}", a.message());
    Ok(())
}

fn verify(
    ctx: &Context,
    class: Option<TrajectoryClass>,
    allow_unapproved: bool,
) -> anyhow::Result<()> {
    let mut failed = Vec::new();
    if let Some(why) = &ctx.trust_problem {
        println!("approvers: NOT TRUSTED — {why}\n  (no approval counts until the site's approvers authority signs these files)");
    }
    for class in classes(class) {
        let (spec, current) = ctx.spec(class)?;
        let lock_path = ctx.layout.lock(class);
        let Ok(lock_text) = ergocell::input::read_text(&lock_path, ergocell::input::Kind::Config)
        else {
            println!(
                "{class}: FAIL\n  - no lock file {} (run `ergocell trajectories lock --class {class}`)",
                lock_path.display()
            );
            failed.push(class);
            continue;
        };
        let approvals_path = ctx.layout.approvals(class);
        let approvals_text =
            ergocell::input::read_text(&approvals_path, ergocell::input::Kind::Config).ok();
        let seen = ergocell::witness::observe_text(
            &approvals_path,
            class,
            approvals_text.as_deref(),
            &ctx.trusted,
            trust_anchor::now_unix(),
        )
        .map(print_notes);
        let inputs = VerifyInputs {
            class,
            lock_toml: &lock_text,
            current_inputs: &current,
            model: &ctx.model,
            approvals_toml: approvals_text.as_deref(),
            trusted: &ctx.trusted,
        };
        // Integrity holds: the samples must also be what validation produces from these inputs.
        if let Ok(lock) = lock::verify_integrity(&inputs) {
            if let Err(e) = matches_validation(ctx, &spec, &current, &lock) {
                println!("{class}: FAIL\n  - {e}");
                failed.push(class);
                continue;
            }
        }
        let verified = lock::verify(&inputs).and_then(|approved| {
            ergocell::session::provider::check_approval_times(&approved, trust_anchor::now_unix())
                .map(|()| approved)
                .map_err(|why| lock::VerifyFailure {
                    class,
                    problems: vec![ergocell_robot::RobotError::Config {
                        reason: why.to_string(),
                    }],
                })
        });
        // The witness's refusal joins the others (a forged entry is also one it did not see).
        let verified = match (verified, seen) {
            (verified, Ok(())) => verified,
            (Ok(_), Err(e)) => Err(lock::VerifyFailure {
                class,
                problems: vec![e],
            }),
            (Err(mut failure), Err(e)) => {
                failure.problems.push(e);
                Err(failure)
            }
        };
        match verified {
            Ok(approved) => {
                let names: Vec<String> = approved
                    .approvals()
                    .iter()
                    .map(|a| {
                        format!(
                            "{} at {} (signature verified)",
                            printable(&a.approved_by),
                            printable(&a.approved_at_utc)
                        )
                    })
                    .collect();
                println!(
                    "{class}: OK — lock_sha256 {} — approved by {}",
                    approved.lock().lock_sha256,
                    names.join(", ")
                );
            }
            Err(failure) => {
                let only_unapproved = failure
                    .problems
                    .iter()
                    .all(|p| matches!(p, ergocell_robot::RobotError::NotApproved { .. }));
                if allow_unapproved && only_unapproved {
                    println!("{class}: INTEGRITY OK, NOT APPROVED — the controller will refuse to run it");
                    for p in &failure.problems {
                        println!("  - {p}");
                    }
                } else {
                    println!("{class}: FAIL");
                    for p in &failure.problems {
                        println!("  - {p}");
                    }
                    failed.push(class);
                }
            }
        }
    }
    if failed.is_empty() {
        Ok(())
    } else {
        bail!("verification failed: {}", list(&failed))
    }
}

/// The site's approvers authority signs the approvers' files (see [`Sub::SignApprovers`]). When the
/// authority is installed here the signature is checked against it before it is written; a
/// signature it would refuse is never written.
fn sign_approvers(ctx: &Context, key: Option<&Path>, signed: Option<&Path>) -> anyhow::Result<()> {
    let (allowed, revoked) = &ctx.trust_texts;
    let signature = match (key, signed) {
        (Some(key_path), None) => {
            let key = signing::private_key_from_openssh(&read(key_path)?)
                .map_err(|e| UsageError(format!("{}: {e}", key_path.display())))?;
            authority::sign_approvers(allowed, revoked, &key)?
        }
        (None, Some(sig_path)) => read(sig_path)?,
        _ => {
            return Err(
                UsageError("sign-approvers needs one of --key or --signed".to_owned()).into(),
            )
        }
    };
    let anchor = trust_anchor::anchor_dir();
    let (checked, usable) = match trust_anchor::load_authority(&anchor) {
        Ok(authority) => {
            let trusted = authority
                .verify(allowed, revoked, &signature)
                .map_err(|e| anyhow::anyhow!("{e}\nrefusing to write the signature"))?;
            (
                format!(
                    "checked against the site's approvers authority in {} ({})",
                    anchor.display(),
                    authority.fingerprints()
                ),
                trusted.usable_keys(),
            )
        }
        Err(trust_anchor::AnchorError::Missing(path)) => (
            format!(
                "NOT checked: no approvers authority is installed here ({} does not exist); the \
                 cell trusts these approvers only if its authority holds the signing key",
                path.display()
            ),
            TrustedSigners::parse(allowed, revoked)?.usable_keys(),
        ),
        Err(e) => bail!("{e}\nrefusing to write the signature"),
    };
    let path = ctx.cell_dir.join(authority::APPROVERS_SIGNATURE);
    write(&path, &signature)?;
    println!(
        "approvers signed: {} ({usable} key(s) trusted, revoked ones not counted; {})",
        path.display(),
        checked
    );
    Ok(())
}

fn list(classes: &[TrajectoryClass]) -> String {
    classes
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(", ")
}

/// Writes a lock or an approvals file atomically (`output::replace`): a full disk or a kill leaves
/// the previous file whole, never cut mid-signature.
fn write(path: &Path, text: &str) -> anyhow::Result<()> {
    if let Some(dir) = path.parent() {
        fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    }
    Ok(super::output::replace(path, text.as_bytes())?)
}

/// Writes `text` to a file that must not exist yet (never overwrites: the user's data is kept).
fn write_new(path: &Path, text: &str) -> anyhow::Result<()> {
    use std::io::Write as _;
    let mut f = fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(path)
        .with_context(|| format!("cannot create {} (it must not exist yet)", path.display()))?;
    f.write_all(text.as_bytes())
        .with_context(|| format!("cannot write {}", path.display()))
}

/// Current UTC time as RFC 3339 (the binary is the only place that reads the clock).
#[allow(clippy::disallowed_methods)]
fn now_rfc3339() -> anyhow::Result<String> {
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    Ok(signing::rfc3339_utc(i64::try_from(secs)?)?)
}
