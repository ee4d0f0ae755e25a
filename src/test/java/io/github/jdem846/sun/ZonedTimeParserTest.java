package io.github.jdem846.sun;

import static io.github.jdem846.sun.SolarCalculatorTest.assertMessage;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Instant;
import java.time.ZoneId;
import java.time.ZoneOffset;
import java.time.ZonedDateTime;
import org.junit.jupiter.api.Test;

class ZonedTimeParserTest {

    @Test
    void offsetTimes() {
        ZonedDateTime t = ZonedTimeParser.parse("2003-10-17T12:30:30-07:00");
        assertEquals(ZoneOffset.ofHours(-7), t.getZone());
        assertEquals(Instant.parse("2003-10-17T19:30:30Z"), t.toInstant());
        assertEquals(Instant.parse("2024-06-21T03:00:00Z"), ZonedTimeParser.parse("2024-06-21T03:00Z").toInstant());
        assertEquals(Instant.parse("2024-06-21T03:00:00.250Z"),
                ZonedTimeParser.parse(" 2024-06-21T05:00:00.25+02:00 ").toInstant());
    }

    @Test
    void zoneIdTimes() {
        ZonedDateTime t = ZonedTimeParser.parse("2024-06-21T05:00[Europe/Luxembourg]");
        assertEquals(ZoneId.of("Europe/Luxembourg"), t.getZone());
        assertEquals(Instant.parse("2024-06-21T03:00:00Z"), t.toInstant()); // CEST
        ZonedDateTime winter = ZonedTimeParser.parse("2024-12-21T05:00[Europe/Luxembourg]");
        assertEquals(Instant.parse("2024-12-21T04:00:00Z"), winter.toInstant()); // CET
        ZonedDateTime both = ZonedTimeParser.parse("2024-06-21T05:00+02:00[Europe/Luxembourg]");
        assertEquals(t, both);
    }

    @Test
    void clockChangesNeedAnOffset() {
        assertMessage(() -> ZonedTimeParser.parse("2024-03-31T02:30[Europe/Luxembourg]"), "does not exist");
        assertMessage(() -> ZonedTimeParser.parse("2024-10-27T02:30[Europe/Luxembourg]"), "happens twice");
        ZonedDateTime first = ZonedTimeParser.parse("2024-10-27T02:30+02:00[Europe/Luxembourg]");
        ZonedDateTime second = ZonedTimeParser.parse("2024-10-27T02:30+01:00[Europe/Luxembourg]");
        assertEquals(3600, second.toEpochSecond() - first.toEpochSecond());
    }

    @Test
    void refusals() {
        assertMessage(() -> ZonedTimeParser.parse("2024-06-21T05:00"), "add one");
        assertMessage(() -> ZonedTimeParser.parse("2024-06-21T05:00"), "2024-06-21T05:00Z");
        assertMessage(() -> ZonedTimeParser.parse("2024-06-21"), "ISO-8601");
        assertMessage(() -> ZonedTimeParser.parse("noon"), "ISO-8601");
        assertMessage(() -> ZonedTimeParser.parse(""), "no time");
        assertMessage(() -> ZonedTimeParser.parse("2024-06-21T05:00[Europe/Luxemburg]"), "unknown time zone");
        assertMessage(() -> ZonedTimeParser.parse("2024-06-21T05:00+05:00[Europe/Luxembourg]"), "+02:00");
        assertMessage(() -> ZonedTimeParser.parse("2024-13-21T05:00Z"), "ISO-8601");
    }
}
