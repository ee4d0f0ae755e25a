package io.github.jdem846.sun;

import java.time.DateTimeException;
import java.time.LocalDateTime;
import java.time.ZoneId;
import java.time.ZoneOffset;
import java.time.ZonedDateTime;
import java.time.format.DateTimeFormatter;
import java.time.format.DateTimeFormatterBuilder;
import java.time.format.DateTimeParseException;
import java.time.temporal.TemporalAccessor;
import java.time.temporal.TemporalQueries;
import java.time.zone.ZoneRules;
import java.util.List;

/**
 * Reads the time of a sun position: ISO-8601 local date and time followed by a UTC offset, a zone id in brackets, or
 * both, e.g. {@code 2003-10-17T12:30:30-07:00}, {@code 2024-06-21T05:00Z},
 * {@code 2024-06-21T05:00[Europe/Luxembourg]} or {@code 2024-06-21T05:00+02:00[Europe/Luxembourg]}. A time without
 * offset or zone is refused (the sun depends on the instant, so the tool will not guess a zone), as is a local time
 * that a zone skips or repeats at a clock change (unless an offset says which), and an offset that the zone does
 * not have at that time.
 */
public final class ZonedTimeParser {

    private static final DateTimeFormatter FORMAT = new DateTimeFormatterBuilder()
            .append(DateTimeFormatter.ISO_LOCAL_DATE_TIME)
            .optionalStart().appendOffsetId().optionalEnd()
            .optionalStart().appendLiteral('[').parseCaseSensitive().appendZoneRegionId().appendLiteral(']')
            .optionalEnd()
            .toFormatter();

    private ZonedTimeParser() {
    }

    /**
     * Parses {@code text} (see the class comment).
     *
     * @param text the date and time as written by the user
     * @return the date and time in the zone written or implied
     * @throws IllegalArgumentException with a message that says what is wrong and what to write
     */
    public static ZonedDateTime parse(String text) {
        String example = "e.g. 2024-06-21T05:00+02:00, 2024-06-21T03:00Z or 2024-06-21T05:00[Europe/Luxembourg]";
        if (text == null || text.isBlank()) {
            throw new IllegalArgumentException("no time given; expected an ISO-8601 date and time with a UTC offset "
                    + "or a zone, " + example);
        }
        String s = text.strip();
        TemporalAccessor parsed;
        try {
            parsed = FORMAT.parse(s);
        } catch (DateTimeParseException e) {
            throw new IllegalArgumentException(explain(s, example), e);
        }
        LocalDateTime local = LocalDateTime.from(parsed);
        ZoneOffset offset = parsed.query(TemporalQueries.offset());
        ZoneId zone = parsed.query(TemporalQueries.zoneId());
        if (offset == null && zone == null) {
            throw new IllegalArgumentException("the time '" + s + "' has no UTC offset or zone, so it names no "
                    + "instant: add one, e.g. " + s + "Z (UTC), " + s + "+02:00 or " + s + "[Europe/Luxembourg]");
        }
        if (zone == null) {
            return ZonedDateTime.of(local, offset);
        }
        ZoneRules rules = zone.getRules();
        List<ZoneOffset> valid = rules.getValidOffsets(local);
        if (offset != null) {
            if (!valid.contains(offset)) {
                throw new IllegalArgumentException("the offset " + offset + " in '" + s + "' is not the offset of "
                        + zone + " at that time" + (valid.isEmpty() ? " (that local time does not exist there)"
                        : " (" + join(valid) + ")") + "; correct or drop one of them");
            }
            return ZonedDateTime.ofLocal(local, zone, offset);
        }
        if (valid.isEmpty()) {
            throw new IllegalArgumentException("the local time " + local + " does not exist in " + zone
                    + " (the clocks jump forward then); write it with the offset you mean, e.g. " + local
                    + rules.getTransition(local).getOffsetBefore());
        }
        if (valid.size() > 1) {
            throw new IllegalArgumentException("the local time " + local + " happens twice in " + zone
                    + " (the clocks go back then); add the offset to say which: " + local + valid.get(0) + "["
                    + zone + "] or " + local + valid.get(1) + "[" + zone + "]");
        }
        return ZonedDateTime.ofLocal(local, zone, valid.get(0));
    }

    private static String explain(String s, String example) {
        int bracket = s.indexOf('[');
        if (bracket >= 0 && s.endsWith("]")) {
            String id = s.substring(bracket + 1, s.length() - 1);
            try {
                ZoneId.of(id);
            } catch (DateTimeException e) {
                return "unknown time zone '" + id + "' in '" + s + "': use a region id such as Europe/Luxembourg, "
                        + "America/Denver or UTC";
            }
        }
        return "cannot read the time '" + s + "': expected an ISO-8601 date and time with a UTC offset or a zone, "
                + example;
    }

    private static String join(List<ZoneOffset> offsets) {
        return offsets.size() == 1 ? offsets.get(0).toString() : offsets.get(0) + " or " + offsets.get(1);
    }
}
