/**
 * The driver for the Sony Aibo ERS-7 running Tekkotsu: one connection per Tekkotsu server,
 * decoded into HABLA channels.
 */
package org.habla.drivers.tekkotsu;
