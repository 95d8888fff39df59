//! Store-and-forward of `plc mqtt serve`: the broker stopped while values change, then started
//! again; the independent host (see `tests/sparkplug.rs`) gets the births and then every
//! stored change, in order, marked historical.

mod common;
mod owner;
mod spb;

use common::plc;
use owner::Owner;
use serde_json::{Value, json};
use spb::{Host, broker_with, free_port, is, metric, parts, serve, test_dir};
use std::time::{Duration, Instant};

#[test]
fn owner_role() {
    if std::env::var("PLC_TEST_ROLE").as_deref() == Ok("owner") {
        owner::run();
    }
}

#[test]
fn changes_while_the_broker_is_away_arrive_after_the_births_in_order_marked_historical() {
    let Some((python, mosquitto)) = parts() else {
        return;
    };
    let dir = test_dir("store");
    let port = free_port();
    let conf = format!("listener {port} 127.0.0.1\nallow_anonymous true\n");
    let broker = broker_with(&mosquitto, &dir, &conf, &[port]);
    let program = Owner::start("spb_store");
    let seg = program.segment.clone();
    let mut host = Host::start(&python, port, "plant", "scada");
    // The primary host's STATE holds the births back until the host is subscribed again
    // after the broker's restart (mosquitto forgets retained messages without persistence).
    host.send(json!({"op": "state", "online": true, "timestamp": 1000}));
    let mut edge = serve(&dir, 1, port, &seg, &["--primary-host", "scada"]);
    host.expect("NBIRTH", is("NBIRTH"));
    host.expect("DBIRTH", is("DBIRTH"));

    drop(broker);
    std::thread::sleep(Duration::from_millis(500));
    assert!(plc(&["set", &seg, "speed_setpoint=444"]).status.success());
    // Ten seconds away, as a broker's restart or a switch's reboot might take.
    std::thread::sleep(Duration::from_secs(10));
    let _broker = broker_with(&mosquitto, &dir, &conf, &[port]);
    host.expect("the host subscribed again", |v| v["ready"] == true);
    host.send(json!({"op": "state", "online": true, "timestamp": 2000}));
    let nbirth = host.expect("NBIRTH after the broker's return", is("NBIRTH"));
    assert!(metric(&nbirth, "bdSeq")["value"].as_i64() > Some(0));
    let dbirth = host.expect("DBIRTH after the broker's return", is("DBIRTH"));
    assert_eq!(metric(&dbirth, "speed_setpoint")["value"], 444);
    let born_counter = metric(&dbirth, "counter")["value"]
        .as_i64()
        .expect("counter");

    // Historical data first, then live data.
    let mut historical: Vec<Value> = Vec::new();
    let deadline = Instant::now() + Duration::from_secs(30);
    loop {
        assert!(
            Instant::now() < deadline,
            "no live data after the historical data"
        );
        let v = host.expect("DDATA", is("DDATA"));
        let ms = v["metrics"].as_array().expect("metrics").clone();
        if ms.iter().all(|m| m["is_historical"] == true) {
            historical.extend(ms);
        } else {
            assert!(ms.iter().all(|m| m["is_historical"] == false), "{v}");
            break;
        }
    }
    let counters: Vec<(i64, i64)> = historical
        .iter()
        .filter(|m| m["name"] == "counter")
        .map(|m| {
            (
                m["value"].as_i64().expect("a number"),
                m["timestamp"].as_i64().expect("a time"),
            )
        })
        .collect();
    // The counter moves every 5 ms and the node looks every 10 ms: ten seconds away make up
    // to a thousand stored values (fewer when a loaded machine wakes the node late).
    assert!(
        counters.len() > 200,
        "{} stored counter values",
        counters.len()
    );
    assert!(
        counters
            .windows(2)
            .all(|w| w[1].0 > w[0].0 && w[1].1 >= w[0].1),
        "stored values in order, each once, with their cycles' times"
    );
    assert!(counters.last().is_some_and(|c| c.0 <= born_counter));
    assert!(
        historical
            .iter()
            .any(|m| m["name"] == "speed_setpoint" && m["value"] == 444),
        "the change made while the broker was away is among the stored values"
    );
    assert!(edge.terminate().is_ok_and(|s| s.success()));
    drop(program);
    let _ = std::fs::remove_dir_all(&dir);
}
