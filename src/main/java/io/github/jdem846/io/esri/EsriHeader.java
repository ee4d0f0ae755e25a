package io.github.jdem846.io.esri;

import io.github.jdem846.io.DemFormatException;
import io.github.jdem846.io.source.RegularFiles;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * The {@code key value} lines of an ESRI header ({@code .hdr} of GridFloat and BIL, the head of an ASCII grid):
 * keys are case-insensitive, the first blank-separated word of a line; the rest of the line is the value. Typed
 * getters fail with a message naming the file, the key and what would be right.
 */
final class EsriHeader {

    private final Path file;
    private final Map<String, String> values;

    private EsriHeader(Path file, Map<String, String> values) {
        this.file = file;
        this.values = values;
    }

    /** Reads a header file (refusing a FIFO or device, whose read could block). */
    static EsriHeader read(Path hdr, String whatNeedsIt) throws DemFormatException {
        RegularFiles.require(hdr, "a header");
        List<String> lines;
        try {
            lines = Files.readAllLines(hdr, StandardCharsets.ISO_8859_1);
        } catch (NoSuchFileException e) {
            throw new DemFormatException(hdr, "header file not found (" + whatNeedsIt + ")");
        } catch (IOException e) {
            throw new DemFormatException(hdr, "cannot read the header: " + e.getMessage(), e);
        }
        return parse(hdr, lines);
    }

    /** Parses header lines (blank lines and lines starting with '#' or '/' are skipped). */
    static EsriHeader parse(Path file, List<String> lines) {
        Map<String, String> map = new LinkedHashMap<>();
        for (String line : lines) {
            String t = line.strip();
            if (t.isEmpty() || t.startsWith("#") || t.startsWith("/")) {
                continue;
            }
            String[] kv = t.split("\\s+", 2);
            map.put(kv[0].toLowerCase(Locale.ROOT), kv.length > 1 ? kv[1].strip() : "");
        }
        return new EsriHeader(file, map);
    }

    Path file() {
        return file;
    }

    boolean has(String key) {
        return values.containsKey(key);
    }

    /** The first of {@code keys} present, or empty. */
    Optional<String> firstPresent(String... keys) {
        for (String k : keys) {
            if (has(k)) {
                return Optional.of(k);
            }
        }
        return Optional.empty();
    }

    Optional<String> string(String key) {
        return Optional.ofNullable(values.get(key));
    }

    /** A whole number ≥ 1. */
    int positiveInt(String key) throws DemFormatException {
        String v = require(key);
        long n;
        try {
            n = Long.parseLong(stripDecimalZeros(v));
        } catch (NumberFormatException e) {
            throw garbled(key, v, "a whole number");
        }
        if (n < 1 || n > Integer.MAX_VALUE) {
            throw new DemFormatException(file, "header key '" + key + "' is " + v
                    + "; it must be a whole number from 1 to " + Integer.MAX_VALUE);
        }
        return (int) n;
    }

    /** A whole number ≥ 0, or {@code dflt} when the key is absent. */
    long nonNegativeLong(String key, long dflt) throws DemFormatException {
        if (!has(key)) {
            return dflt;
        }
        String v = values.get(key);
        long n;
        try {
            n = Long.parseLong(stripDecimalZeros(v));
        } catch (NumberFormatException e) {
            throw garbled(key, v, "a whole number");
        }
        if (n < 0) {
            throw new DemFormatException(file, "header key '" + key + "' is " + v + "; it must not be negative");
        }
        return n;
    }

    /** A finite number. */
    double finite(String key) throws DemFormatException {
        String v = require(key);
        double d = parse(key, v);
        if (!Double.isFinite(d)) {
            throw garbled(key, v, "a finite number");
        }
        return d;
    }

    /** A positive finite number. */
    double positive(String key) throws DemFormatException {
        double d = finite(key);
        if (!(d > 0)) {
            throw new DemFormatException(file, "header key '" + key + "' is " + values.get(key)
                    + "; it must be a positive number");
        }
        return d;
    }

    /** A number (NaN allowed, written "nan"), or empty when the key is absent. */
    Optional<Double> optionalNumber(String key) throws DemFormatException {
        if (!has(key)) {
            return Optional.empty();
        }
        return Optional.of(parse(key, values.get(key)));
    }

    /** The number under the first of {@code keys} present (NaN allowed), or empty when none is. */
    Optional<Double> firstNumber(String... keys) throws DemFormatException {
        Optional<String> key = firstPresent(keys);
        return key.isPresent() ? optionalNumber(key.get()) : Optional.empty();
    }

    private String require(String key) throws DemFormatException {
        String v = values.get(key);
        if (v == null) {
            throw new DemFormatException(file, "header key '" + key + "' is missing");
        }
        if (v.isEmpty()) {
            throw new DemFormatException(file, "header key '" + key + "' has no value");
        }
        return v;
    }

    private double parse(String key, String v) throws DemFormatException {
        if (v.equalsIgnoreCase("nan")) {
            return Double.NaN;
        }
        try {
            return Double.parseDouble(v);
        } catch (NumberFormatException e) {
            throw garbled(key, v, "a number");
        }
    }

    private DemFormatException garbled(String key, String v, String expected) {
        return new DemFormatException(file, "header key '" + key + "' is '" + v + "', not " + expected);
    }

    /** "1197.0" → "1197", so headers written by float-printing tools still give whole numbers. */
    private static String stripDecimalZeros(String v) {
        return v.matches("[+-]?\\d+\\.0*") ? v.substring(0, v.indexOf('.')) : v;
    }
}
