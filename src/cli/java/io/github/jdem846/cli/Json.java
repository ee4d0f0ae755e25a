package io.github.jdem846.cli;

import java.util.List;

/**
 * A tiny JSON writer for one flat-ish object: string escaping (RFC 8259), numbers (non-finite become
 * {@code null}) and nesting by hand. No JSON library is needed for the CLI's small reports.
 */
final class Json {

    private final StringBuilder out = new StringBuilder();
    private boolean first = true;

    Json() {
        out.append('{');
    }

    /** Adds {@code "key": "value"} (or null). */
    Json string(String key, String value) {
        return raw(key, value == null ? "null" : quote(value));
    }

    /** Adds {@code "key": number} ({@code null} when NaN or infinite). */
    Json number(String key, double value) {
        return raw(key, number(value));
    }

    /** Adds {@code "key": integer} (or null). */
    Json integer(String key, Long value) {
        return raw(key, value == null ? "null" : Long.toString(value));
    }

    Json bool(String key, boolean value) {
        return raw(key, Boolean.toString(value));
    }

    /** Adds {@code "key": [strings]}. */
    Json strings(String key, List<String> values) {
        StringBuilder sb = new StringBuilder("[");
        for (int i = 0; i < values.size(); i++) {
            sb.append(i > 0 ? ", " : "").append(quote(values.get(i)));
        }
        return raw(key, sb.append(']').toString());
    }

    /** Adds {@code "key": <already formatted JSON>}. */
    Json raw(String key, String json) {
        out.append(first ? "" : ", ").append(quote(key)).append(": ").append(json);
        first = false;
        return this;
    }

    /** The object text. */
    @Override
    public String toString() {
        return out + "}";
    }

    /** A number as JSON: integral values without a fraction, non-finite as {@code null}. */
    static String number(double v) {
        if (!Double.isFinite(v)) {
            return "null";
        }
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        return Double.toString(v);
    }

    /** A JSON string literal. */
    static String quote(String s) {
        StringBuilder sb = new StringBuilder(s.length() + 2).append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"' -> sb.append("\\\"");
                case '\\' -> sb.append("\\\\");
                case '\n' -> sb.append("\\n");
                case '\r' -> sb.append("\\r");
                case '\t' -> sb.append("\\t");
                case '\b' -> sb.append("\\b");
                case '\f' -> sb.append("\\f");
                default -> {
                    if (c < 0x20) {
                        sb.append(String.format("\\u%04x", (int) c));
                    } else {
                        sb.append(c);
                    }
                }
            }
        }
        return sb.append('"').toString();
    }
}
