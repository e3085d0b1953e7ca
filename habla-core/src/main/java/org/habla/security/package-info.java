/** Who may read and who may drive: clients' credentials and roles, the audit log, TLS and the worker link's proof. */
package org.habla.security;
