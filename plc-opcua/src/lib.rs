//! An OPC UA server for the variables of running plc-vars programs (OPC UA, IEC 62541), on
//! async-opcua's server.
//!
//! The server is a tool like `plc`: it attaches to the shared-memory segments of running
//! programs, reads seqlock snapshots and writes through the program's own write path; a control
//! program does not link it, and however slow a client is, the program's cycle never waits for
//! it. `plc opcua serve SEGMENT...` runs it; `plc opcua user add FILE NAME` adds a user who may
//! write.
//!
//! # Address space
//!
//! | OPC UA | plc-vars |
//! | --- | --- |
//! | namespace `urn:plc-vars:<segment>` | a segment |
//! | object `<segment>` under Objects (NodeId `i=1` in its namespace) | the program |
//! | variable `ns=<ns>;s=<path>` under it | a variable, by the path `plc get` takes |
//! | BrowseName, DisplayName | the symbol name as declared |
//! | Description | the description (doc comment) |
//! | DataType | BOOL Boolean, SINT SByte, USINT/BYTE Byte, INT Int16, UINT/WORD UInt16, DINT Int32, UDINT/DWORD UInt32, LINT Int64, ULINT/LWORD UInt64, REAL Float, LREAL Double, STRING String |
//! | ValueRank, ArrayDimensions | an array's dimensions; the array is one value |
//! | AccessLevel | CurrentRead, plus CurrentWrite where a tool may write (read-write, neither input nor status) |
//! | UserAccessLevel | the AccessLevel for users of the users file; CurrentRead only for anonymous sessions |
//! | SourceTimestamp | the UTC time the owner stamped the cycle that produced the value |
//! | StatusCode | Good while the owner runs, GoodLocalOverride for a value held by a force (`plc force`; a node any of whose elements is forced); UncertainLastUsableValue while it is stalled; BadNoCommunication once it is gone, stopped or faulted |
//!
//! Writes are refused with BadNotWritable (input, status, read-only), BadUserAccessDenied
//! (anonymous session), BadOutOfRange (out of range, NaN or an infinity, text too long),
//! BadTypeMismatch (another kind, an array of other dimensions) and BadLocked (a value held by a
//! force: release it first; the log line names who forced it and since when); an array written
//! whole is applied in one cycle, and so is a part of one written with an index range (`2:4`,
//! `1,0:2`, OPC UA's NumericRange; BadIndexRangeNoData past its end). Every write is logged with
//! its user and the old and new value.
//!
//! # Alarms
//!
//! Each alarm of the program is a condition (OPC UA Part 9) under the program's object:
//! `ns=<ns>;s=<path>#alarm`, an OffNormalAlarmType for a bool alarm and an
//! ExclusiveLimitAlarmType for a limit alarm, with ActiveState, AckedState, EnabledState,
//! SuppressedState (suppressed by design), ShelvingState/CurrentState, LimitState/CurrentState
//! (High, HighHigh, Low, LowLow), Severity, Message (the alarm's text), SourceName and
//! ConditionName (its path), Time (the program's time of the transition), Retain (anything
//! but normal), Quality, Comment and ClientUserId of the last acknowledgement, and the limits;
//! each readable (and monitorable) as a variable `…#alarm/ActiveState/Id`. Every transition
//! (raised, acknowledged, returned to normal, shelved, ...) is an event from the program's
//! object (subscribe there, or on Server for every segment), filtered by the subscriber's
//! select and where clauses; ConditionId (the NodeId select clause of ConditionType) is the
//! condition's node. The server reads the program's alarm table every 10 ms and sends at
//! most 256 events a poll per segment (a flood follows over the next polls).
//!
//! Acknowledge (AcknowledgeableConditionType's, `i=9111`, on the condition with the EventId of
//! its last event and a comment) is for users of the users file over Sign or SignAndEncrypt,
//! as writes are: it reaches the program through its socket, and its alarm journal records
//! the user. Refusals: BadUserAccessDenied (anonymous, or not a user), BadEventIdUnknown (not
//! the condition's last event), BadConditionBranchAlreadyAcked (nothing waits for an
//! acknowledgement). ConditionRefresh and ConditionRefresh2 send the calling subscription
//! alone a RefreshStartEvent, the retained conditions and a RefreshEndEvent (through its
//! filters: those have Severity 1).
//!
//! # Security
//!
//! Endpoints: security policy None (anonymous sessions may browse and read) and Basic256Sha256
//! with Sign and with SignAndEncrypt. A user name token must carry its password encrypted with
//! the server's certificate, on every endpoint: one in plain text is refused. The server makes
//! a self-signed certificate in its certificate store on first start; a client's certificate
//! must be in the store's `trusted/` directory for Sign and SignAndEncrypt (a refused one is
//! put in `rejected/`: move it to `trusted/` to allow that client). The users file is read
//! again when it changes (within a second): a user added may sign in, a user removed may no
//! longer write, without a restart; a broken file lets nobody write until it is fixed.

#![deny(missing_docs)]

pub mod address;
pub mod alarms;
pub mod auth;
pub mod gate;
pub mod mapping;
pub mod node_manager;
pub mod rejected;
pub mod sampler;
pub mod server;
pub mod shared;
pub mod signin;
pub mod users;
pub mod users_file;
pub mod writer;

/// async-opcua, as this crate uses it (its types appear in this crate's API).
pub use opcua;
pub use server::{ServeError, ServeLimits, ServeOptions, serve};
pub use users::{Users, UsersError, add_user};
pub use users_file::UsersFile;
