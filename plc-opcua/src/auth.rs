//! Who may do what: anonymous sessions browse and read; users of the users file also write.
//! A user name token must carry its password encrypted with the server's certificate (OPC UA
//! Part 4, 7.41): one sent in plain text is refused while the request is decoded, before the
//! password is looked at. User names are offered only on the signed endpoints (Sign,
//! SignAndEncrypt): a user's writes would otherwise travel unsigned, for anyone on the path to
//! read or change, under the user's name. `--allow-unsigned-writes` offers them on None too,
//! for a closed network.

use crate::mapping;
use crate::signin::SignIns;
use crate::users_file::UsersFile;
use opcua::crypto::SecurityPolicy;
use opcua::nodes::AccessLevel;
use opcua::server::ServerEndpoint;
use opcua::server::authenticator::{AuthManager, Password, UserToken};
use opcua::types::{
    BinaryDecodable, Context, DynEncodable, EncodingResult, Error, MessageSecurityMode, NodeId,
    ObjectId, StatusCode, TypeLoader, TypeLoaderPriority, UAString, UserNameIdentityToken,
    UserTokenPolicy, UserTokenType,
};
use plc_shm::LogLimit;
use std::io::Read;
use std::sync::Arc;

/// The policy id of the anonymous token (the one async-opcua checks).
const POLICY_ANONYMOUS: &str = "anonymous";
/// The policy id async-opcua expects of a user name token whose password is encrypted with
/// RSA-OAEP (Basic256Sha256's asymmetric encryption).
const POLICY_USER_NAME: &str = "userpass_rsa_oaep";

/// Refused sign-ins, logged at a bounded rate.
static REFUSED: LogLimit = LogLimit::new("plc_opcua::auth");

/// The server's authenticator.
pub struct PlcAuth {
    users: Arc<UsersFile>,
    sign_ins: SignIns,
    unsigned_writes: bool,
}

impl PlcAuth {
    /// An authenticator for the users of this file (as it is when each session signs in);
    /// `unsigned_writes`: user names offered on the None endpoint too.
    pub fn new(users: Arc<UsersFile>, unsigned_writes: bool) -> PlcAuth {
        PlcAuth {
            users,
            sign_ins: SignIns::default(),
            unsigned_writes,
        }
    }
}

/// Whether users may sign in (and so write) over a channel of `mode`.
pub fn users_allowed(mode: MessageSecurityMode, unsigned_writes: bool) -> bool {
    unsigned_writes
        || matches!(
            mode,
            MessageSecurityMode::Sign | MessageSecurityMode::SignAndEncrypt
        )
}

#[async_trait::async_trait]
impl AuthManager for PlcAuth {
    async fn authenticate_anonymous_token(&self, _endpoint: &ServerEndpoint) -> Result<(), Error> {
        Ok(())
    }

    async fn authenticate_username_identity_token(
        &self,
        endpoint: &ServerEndpoint,
        username: &str,
        password: &Password,
    ) -> Result<UserToken, Error> {
        // The name is logged only if it is one the file could hold: nothing forged.
        let shown = if crate::users::valid_name(username) {
            username
        } else {
            "?"
        };
        if !users_allowed(endpoint.message_security_mode(), self.unsigned_writes) {
            REFUSED.warn(|| {
                format!(
                    "OPC UA sign-in refused for user `{shown}`: over a channel without \
                     signing (connect with Sign or SignAndEncrypt)"
                )
            });
            return Err(Error::new(
                StatusCode::BadSecurityModeInsufficient,
                "users sign in over Sign or SignAndEncrypt only",
            ));
        }
        let users = self.users.current();
        let password = password.get().to_string();
        if self.sign_ins.check(users, username, password).await {
            log::info!("OPC UA user `{username}` signed in");
            Ok(UserToken(username.to_string()))
        } else {
            REFUSED.warn(|| {
                format!("OPC UA sign-in refused for user `{shown}`: unknown user or wrong password")
            });
            Err(Error::new(
                StatusCode::BadUserAccessDenied,
                "unknown user or wrong password",
            ))
        }
    }

    fn effective_user_access_level(
        &self,
        token: &UserToken,
        user_access_level: AccessLevel,
        _node_id: &NodeId,
    ) -> AccessLevel {
        mapping::user_access_level(user_access_level, !may_write(&self.users, token))
    }

    fn user_token_policies(&self, endpoint: &ServerEndpoint) -> Vec<UserTokenPolicy> {
        let mut policies = vec![UserTokenPolicy {
            policy_id: UAString::from(POLICY_ANONYMOUS),
            token_type: UserTokenType::Anonymous,
            issued_token_type: UAString::null(),
            issuer_endpoint_url: UAString::null(),
            security_policy_uri: UAString::null(),
        }];
        if !self.users.current().is_empty()
            && users_allowed(endpoint.message_security_mode(), self.unsigned_writes)
        {
            // The password travels encrypted with the server's certificate under
            // Basic256Sha256 (on None too, where unsigned writes are allowed).
            policies.push(UserTokenPolicy {
                policy_id: UAString::from(POLICY_USER_NAME),
                token_type: UserTokenType::UserName,
                issued_token_type: UAString::null(),
                issuer_endpoint_url: UAString::null(),
                security_policy_uri: UAString::from(SecurityPolicy::Basic256Sha256.to_uri()),
            });
        }
        policies
    }
}

/// Whether the session of `token` may write: a user of the users file as it is now (one
/// removed since the session signed in no longer may), not an anonymous one.
pub fn may_write(users: &UsersFile, token: &UserToken) -> bool {
    !token.is_anonymous() && users.current().contains(&token.0)
}

/// Decodes user name tokens ahead of the generated decoder and refuses one whose password is
/// not encrypted: async-opcua would otherwise accept it as it came.
#[derive(Debug)]
pub struct RefusePlainTextPasswords;

impl TypeLoader for RefusePlainTextPasswords {
    fn load_from_binary(
        &self,
        node_id: &NodeId,
        stream: &mut dyn Read,
        ctx: &Context<'_>,
        _length: Option<usize>,
    ) -> Option<EncodingResult<Box<dyn DynEncodable>>> {
        let encoding_id: NodeId = ObjectId::UserNameIdentityToken_Encoding_DefaultBinary.into();
        if *node_id != encoding_id {
            return None;
        }
        Some(
            UserNameIdentityToken::decode(stream, ctx).and_then(|token| {
                if token.encryption_algorithm.is_empty() {
                    REFUSED.warn(|| {
                        "OPC UA sign-in refused: a user name token with its password in plain \
                         text (the client must encrypt it with the server's certificate)"
                            .to_string()
                    });
                    Err(Error::new(
                        StatusCode::BadIdentityTokenRejected,
                        "the password of a user name token must be encrypted",
                    ))
                } else {
                    Ok(Box::new(token) as Box<dyn DynEncodable>)
                }
            }),
        )
    }

    fn priority(&self) -> TypeLoaderPriority {
        TypeLoaderPriority::Core
    }
}
