/** {@code habla worker}: runs methods placed on another computer for a daemon, to spread the computational cost. */
package org.habla.worker;
