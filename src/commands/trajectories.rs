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
//! The cell's files, class files, keys and the approvals folder's lock are read and written
//! through `ergocell_host::review_files` (locks and approvals through `ergocell::input`); what they mean and the
//! texts are `ergocell_robot::review`'s and `ergocell_approvals::review`'s.
//!
//! Paths default to `trajectories/` and `config/cell.toml` under the current directory. The lock is a
//! software guarantee on top of the robot's own safety controller, not a replacement for it.

use std::path::{Path, PathBuf};

use anyhow::{bail, Context as _};
use ergocell::trust_anchor;
use ergocell_approvals::review::{untrusted_approvers_text, ApproversSigned, ClassCheck, Verdict};
use ergocell_host::review_files::{
    self, now_rfc3339, read_text as read, write_new, ApprovalsLock, ReviewCell, ReviewFileError,
};
use ergocell_robot::authority;
use ergocell_robot::lock::{self, ApprovalsFile, LockFile};
use ergocell_robot::review::{self, ClassValidation, Refused, SignOff};
use ergocell_robot::signing;
use ergocell_robot::{
    plan_and_validate, InputHashes, TrajectoryClass, TrajectoryLayout, TrajectorySpec, Validation,
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
                authority::approvers_message(&ctx.allowed_signers, &ctx.revoked_keys)
            );
            Ok(())
        }
    }
}

/// The cell read for review (`review_files::ReviewCell`: its robot, the approvers' files and
/// whether they are trusted) and the trajectories folder, read once.
struct Context {
    review: ReviewCell,
    layout: TrajectoryLayout,
}

impl std::ops::Deref for Context {
    type Target = ReviewCell;

    fn deref(&self) -> &ReviewCell {
        &self.review
    }
}

impl Context {
    fn load(args: &Args) -> anyhow::Result<Self> {
        Ok(Self {
            review: ReviewCell::load(&args.cell).map_err(bad_input)?,
            layout: TrajectoryLayout::new(&args.trajectories_dir),
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
        let version = env!("CARGO_PKG_VERSION");
        self.review
            .read_spec(&self.layout, class, version)
            .map_err(bad_input)
    }
}

/// A review file's error as the exit code reads it: a malformed file is a usage error; an unreadable
/// one keeps its `InputError` (bad input too).
fn bad_input(e: ReviewFileError) -> anyhow::Error {
    match e {
        ReviewFileError::Malformed { .. } => UsageError(e.to_string()).into(),
        other => other.into(),
    }
}

/// An OpenSSH private key file (a usage error when it is not one).
fn private_key(path: &Path) -> anyhow::Result<signing::PrivateKey> {
    review_files::read_private_key(path).map_err(bad_input)
}

fn validate(ctx: &Context, class: Option<TrajectoryClass>, json: bool) -> anyhow::Result<()> {
    let mut failed = Vec::new();
    let mut json_out = Vec::new();
    for class in review::selected(class) {
        let (spec, hashes) = ctx.spec(class)?;
        let validation = ClassValidation::plan(class, &ctx.plan_inputs(&spec, &hashes));
        if !validation.accepted() {
            failed.push(class);
        }
        if json {
            json_out.push(validation.json()?);
        } else {
            println!("{}", validation.text());
        }
    }
    if json {
        println!("{}", serde_json::to_string_pretty(&json_out)?);
    }
    if failed.is_empty() {
        Ok(())
    } else {
        bail!("rejected: {}", review::class_list(&failed))
    }
}

/// Validates every class asked for first and writes their locks only when all are accepted: a bad
/// class (or an unreadable trajectory file) leaves every lock as it was, never some re-locked and
/// some not.
fn lock_classes(ctx: &Context, class: Option<TrajectoryClass>) -> anyhow::Result<()> {
    let mut failed = Vec::new();
    let mut bad_input = false;
    let mut locks = Vec::new();
    for class in review::selected(class) {
        match locked(ctx, class) {
            Ok(lock) => locks.push((class, lock)),
            Err(e) => {
                eprintln!("{class}: not locked: {e:#}");
                bad_input |= e.chain().any(<dyn std::error::Error>::is::<UsageError>);
                failed.push(class);
            }
        }
    }
    if !failed.is_empty() {
        let why = review::not_locked_text(&failed);
        // A malformed file is bad input (exit 2); a class that does not validate is a rejection (1).
        return Err(if bad_input {
            UsageError(why).into()
        } else {
            anyhow::anyhow!(why)
        });
    }
    for (class, lock) in locks {
        let path = ctx.layout.lock(class);
        review_files::replace(&path, &lock.to_toml()?)?;
        println!("{}", review::locked_text(&lock, &path));
    }
    if let Some(why) = &ctx.trust_problem {
        eprintln!("{}", review::untrusted_lock_note(why));
    }
    Ok(())
}

/// The class planned, validated and locked from the current files.
fn locked(ctx: &Context, class: TrajectoryClass) -> anyhow::Result<LockFile> {
    let (spec, hashes) = ctx.spec(class)?;
    let locked =
        plan_and_validate(&ctx.plan_inputs(&spec, &hashes)).and_then(Validation::into_locked)?;
    Ok(LockFile::from_locked(&locked))
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
                    .unwrap_or_else(|| review_files::signature_beside(message)),
            }),
            _ => Err(UsageError(
                "needs one of --key <private key>, --message-out <file> or --signed <file>"
                    .to_owned(),
            )),
        }
    }
}

/// The approvals folder's lock (`review_files::ApprovalsLock`) for a command that writes the
/// approvals file, so two engineers approving at once both land: a second command waits, and says
/// it waits; the leftovers of writes that were stopped are removed under it, each said. None for
/// `--message-out`, which only writes the message to sign.
fn approvals_lock(ctx: &Context, how: &ApproveHow<'_>) -> anyhow::Result<Option<ApprovalsLock>> {
    if matches!(how, ApproveHow::MessageOut(_)) {
        return Ok(None);
    }
    let (lock, leftovers) = ApprovalsLock::take(ctx.layout.approvals_dir(), |lock_path| {
        eprintln!(
            "waiting: another approve or withdraw holds {} (it is writing the approvals)",
            lock_path.display()
        );
    })?;
    for leftover in leftovers {
        eprintln!("{leftover}");
    }
    Ok(Some(lock))
}

/// The class's approvals file (empty if there is none yet), its chain checked and checked against
/// the cell's witness ([`ergocell::witness`]): a file cut back is refused before anything is added.
fn load_approvals(ctx: &Context, class: TrajectoryClass) -> anyhow::Result<ApprovalsFile> {
    let path = ctx.layout.approvals(class);
    // A missing file is an empty chain: one the witness saw entries of was deleted.
    let file = review_files::read_approvals(&path).map_err(bad_input)?;
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

/// Approves the class's lock, after checking its integrity and that it holds what validation
/// produces now.
fn approve(
    ctx: &Context,
    class: TrajectoryClass,
    by: Option<&str>,
    how: ApproveHow<'_>,
) -> anyhow::Result<()> {
    Refused::unless_trusted(ctx.trust_problem.as_deref(), "approve")?;
    let (spec, current) = ctx.spec(class)?;
    let lock_text = read(&ctx.layout.lock(class))
        .with_context(|| format!("run `ergocell trajectories lock --class {class}` first"))?;
    let lock = lock::verify_integrity(&ctx.verify_inputs(class, &lock_text, &current, None))
        .map_err(|failure| Refused::Integrity { failure })?;
    review::revalidate(&ctx.plan_inputs(&spec, &current), &lock)
        .map_err(|cause| Refused::NotValidated { cause })?;
    sign_off(ctx, SignOff::Approve(&lock), by, how)
}

/// Withdraws the class's standing approval.
fn withdraw(
    ctx: &Context,
    class: TrajectoryClass,
    by: Option<&str>,
    how: ApproveHow<'_>,
) -> anyhow::Result<()> {
    Refused::unless_trusted(ctx.trust_problem.as_deref(), "withdraw")?;
    let approvals_path = ctx.layout.approvals(class);
    if !approvals_path.exists() {
        return Err(UsageError(format!(
            "{} does not exist: {class} has no approval to withdraw",
            approvals_path.display()
        ))
        .into());
    }
    sign_off(ctx, SignOff::Withdraw(class), by, how)
}

/// Appends the approval or withdrawal `what` to the class's approvals file, signed as `how` says,
/// under the approvals folder's lock; or, with `--message-out`, writes the message to sign.
fn sign_off(
    ctx: &Context,
    what: SignOff<'_>,
    by: Option<&str>,
    how: ApproveHow<'_>,
) -> anyhow::Result<()> {
    let class = what.class();
    let approvals_path = ctx.layout.approvals(class);
    let _lock = approvals_lock(ctx, &how)?;
    let mut file = load_approvals(ctx, class)?;
    let by = by.unwrap_or_default();
    let entry = match how {
        ApproveHow::Key(key_path) => {
            let key = private_key(key_path)?;
            what.sign(&mut file, by, &now_rfc3339()?, &ctx.trusted, &key)?
                .clone()
        }
        ApproveHow::MessageOut(out) => {
            write_new(out, &what.message(&file, by, &now_rfc3339()?)?)?;
            println!("{}", what.message_written_text(out));
            return Ok(());
        }
        ApproveHow::Signed { message, signature } => {
            let text = read(message)?;
            let sig = read(&signature)?;
            what.append_signed(&mut file, &text, &sig, &ctx.trusted)?
                .clone()
        }
    };
    review::check_entry_time(&entry, trust_anchor::now_unix())?;
    review_files::replace(&approvals_path, &file.to_toml()?)?;
    witness(ctx, &approvals_path, class, &file)?;
    println!("{}", review::recorded_text(class, &entry, &approvals_path));
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
    let a = review::entry_to_show(&file, entry, &path).map_err(|e| UsageError(e.to_string()))?;
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
        println!("{}", untrusted_approvers_text(why));
    }
    for class in review::selected(class) {
        let verdict = verdict(ctx, class, allow_unapproved)?;
        println!("{}", verdict.text());
        if !verdict.passes() {
            failed.push(class);
        }
    }
    if failed.is_empty() {
        Ok(())
    } else {
        bail!("verification failed: {}", review::class_list(&failed))
    }
}

/// One class's lock and approvals as they are on disk, after the witness has seen the approvals
/// (its notes on standard error).
fn verdict(
    ctx: &Context,
    class: TrajectoryClass,
    allow_unapproved: bool,
) -> anyhow::Result<Verdict> {
    use ergocell::input::{read_text, Kind};
    let (spec, current) = ctx.spec(class)?;
    let lock_path = ctx.layout.lock(class);
    let Ok(lock_text) = read_text(&lock_path, Kind::Config) else {
        return Ok(Verdict::no_lock(class, &lock_path));
    };
    let approvals_path = ctx.layout.approvals(class);
    let approvals_text = read_text(&approvals_path, Kind::Config).ok();
    let approvals_text = approvals_text.as_deref();
    let witness = ergocell::witness::observe_text(
        &approvals_path,
        class,
        approvals_text,
        &ctx.trusted,
        trust_anchor::now_unix(),
    )
    .map(print_notes);
    let check = ClassCheck {
        inputs: ctx.verify_inputs(class, &lock_text, &current, approvals_text),
        cell: &ctx.cell,
        spec: &spec,
        witness,
        now_unix: trust_anchor::now_unix(),
    };
    Ok(Verdict::of(check, allow_unapproved))
}

/// The site's approvers authority signs the approvers' files (see [`Sub::SignApprovers`]). When the
/// authority is installed here the signature is checked against it before it is written; a
/// signature it would refuse is never written.
fn sign_approvers(ctx: &Context, key: Option<&Path>, signed: Option<&Path>) -> anyhow::Result<()> {
    let (allowed, revoked) = (&ctx.allowed_signers, &ctx.revoked_keys);
    let signature = match (key, signed) {
        (Some(key_path), None) => {
            authority::sign_approvers(allowed, revoked, &private_key(key_path)?)?
        }
        (None, Some(sig_path)) => read(sig_path)?,
        _ => {
            return Err(
                UsageError("sign-approvers needs one of --key or --signed".to_owned()).into(),
            )
        }
    };
    let anchor = trust_anchor::anchor_dir();
    let installed = trust_anchor::load_authority(&anchor);
    let checked = ApproversSigned::check(installed, &anchor, allowed, revoked, &signature)?;
    let path = ctx.cell_dir.join(authority::APPROVERS_SIGNATURE);
    review_files::replace(&path, &signature)?;
    println!("{}", checked.text(&path));
    Ok(())
}
