/** Config: the JSON file read strictly into immutable records, with every error reported at its JSON path. */
package org.habla.config;
