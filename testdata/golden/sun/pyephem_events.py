"""Sunrise, transit and sunset from PyEphem (an engine independent of NREL SPA) for SolarCalculatorTest."""
import ephem


def events(name, lat, lon, date):
    o = ephem.Observer()
    o.lat, o.lon = str(lat), str(lon)
    o.elevation = 0
    # USNO almanac convention: no pressure-based refraction, horizon −34′, upper limb (PyEphem's default)
    o.pressure = 0
    o.horizon = '-0:34'
    o.date = date
    s = ephem.Sun()
    r, t, st = o.next_rising(s), o.next_transit(s), o.next_setting(s)
    print(name, date, 'UTC rise', r, 'transit', t, 'set', st)


events('Luxembourg', 49.6116, 6.1319, '2024/6/21 00:00')
events('Zurich', 47.3769, 8.5417, '2018/6/21 00:00')
events('Golden', 39.742476, -105.1786, '2003/10/17 07:00')
